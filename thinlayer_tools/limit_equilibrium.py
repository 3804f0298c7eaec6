#!/usr/bin/python3
"""The safety factor of a simple slope by Bishop's simplified method of
slices (Bishop 1955), minimised over circular slip surfaces.

The slope of meshes/slope.geo without a foundation layer (Griffiths and
Lane's depth factor D = 1): ground at y = H behind the crest at x = 0, a
straight face down to the toe at (run H, 0), a firm base at y = 0 that no
circle may cross. Bishop's method satisfies the moment equilibrium of the
sliding mass about the circle's centre and each slice's vertical
equilibrium, neglecting the shear between slices; Bishop and Morgenstern's
(1960) charts tabulate it. A limit-equilibrium value is neither a bound nor
exact; Griffiths and Lane (1999) found strength-reduction finite elements
within about 2% of it for the homogeneous slope. Run as a script, prints the
factor and the critical circle for the slope of prm/slope-strength-reduction.prm.
"""
import argparse
import math


def bishop_factor(centre, radius, height, run, cohesion, phi_degrees, weight, slices=100):
    """Bishop's simplified factor of one circle (None when the circle does
    not cut the face or the crest's ground, or dips below the base)."""
    xc, yc = centre
    if yc - radius < -1e-12:
        return None

    def ground(x):
        if x <= 0:
            return height
        if x >= run * height:
            return 0.0
        return height - x / run

    # The circle's lower arc y = yc - sqrt(r^2 - (x - xc)^2) cuts the ground
    # at an entry x_a (behind, higher) and an exit x_b (lower).
    def below(x):
        d = radius * radius - (x - xc) ** 2
        return yc - math.sqrt(d) if d > 0 else None

    left, right = xc - radius, xc + radius
    samples = 400
    xs = [left + (right - left) * (i + 0.5) / samples for i in range(samples)]
    inside = [x for x in xs if below(x) is not None and below(x) < ground(x)]
    if len(inside) < 10:
        return None
    step = (right - left) / samples

    def crossing(inner, outer):
        # Bisect between a point inside the sliding mass and one outside.
        for _ in range(50):
            mid = 0.5 * (inner + outer)
            y = below(mid)
            if y is not None and y < ground(mid):
                inner = mid
            else:
                outer = mid
        return inner

    x_a = crossing(inside[0], inside[0] - step)
    x_b = crossing(inside[-1], inside[-1] + step)
    tan_phi = math.tan(math.radians(phi_degrees))
    width = (x_b - x_a) / slices
    pieces = []
    driving = 0.0
    for i in range(slices):
        x = x_a + (i + 0.5) * width
        y = below(x)
        h = ground(x) - y
        if h <= 0:
            continue
        w = weight * h * width
        sin_a = (xc - x) / radius  # the base rises towards the entry side
        cos_a = math.sqrt(max(0.0, 1 - sin_a * sin_a))
        driving += w * sin_a
        pieces.append((w, sin_a, cos_a))
    if driving <= 0:
        return None
    factor = 1.0
    for _ in range(100):
        resisting = 0.0
        for w, sin_a, cos_a in pieces:
            m = cos_a + sin_a * tan_phi / factor
            if m <= 0.05:
                return None
            resisting += (cohesion * width + w * tan_phi) / m
        new = resisting / driving
        if abs(new - factor) < 1e-10:
            break
        factor = new
    return factor


def critical_circle(height, run, cohesion, phi_degrees, weight):
    """The least Bishop factor over circles through the toe or above it,
    by a grid over centres and radii refined twice around the best."""
    best = (math.inf, None, None)
    span_x = (-1.5 * height, 2.0 * run * height)
    span_y = (0.5 * height, 4.0 * height)
    for level in range(3):
        n = 16
        for i in range(n + 1):
            xc = span_x[0] + (span_x[1] - span_x[0]) * i / n
            for j in range(n + 1):
                yc = span_y[0] + (span_y[1] - span_y[0]) * j / n
                for k in range(1, n + 1):
                    # Radii from the circle through the crest's level to
                    # the one touching the base.
                    radius = (yc - height) + (height) * k / n if yc > height else yc * k / n
                    radius = min(radius, yc)
                    f = bishop_factor((xc, yc), radius, height, run, cohesion, phi_degrees, weight)
                    if f is not None and f < best[0]:
                        best = (f, (xc, yc), radius)
        (xc, yc), dx, dy = best[1], (span_x[1] - span_x[0]) / 8, (span_y[1] - span_y[0]) / 8
        span_x, span_y = (xc - dx, xc + dx), (max(0.1 * height, yc - dy), yc + dy)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--height", type=float, default=10)
    parser.add_argument("--run", type=float, default=2)
    parser.add_argument("--cohesion", type=float, default=10)
    parser.add_argument("--phi", type=float, default=20)
    parser.add_argument("--weight", type=float, default=20)
    args = parser.parse_args()
    factor, centre, radius = critical_circle(args.height, args.run, args.cohesion, args.phi, args.weight)
    print(f"Bishop's simplified factor {factor:.4f}, circle centre ({centre[0]:.2f}, {centre[1]:.2f}) radius {radius:.2f}")


if __name__ == "__main__":
    main()
