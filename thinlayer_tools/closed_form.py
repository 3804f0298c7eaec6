#!/usr/bin/python3
"""Closed-form values the scripts and benchmarks compare thinlayer against.

Each function names the body it is exact (or a bound) for, so that a table
can say which truth a computed value is measured against. Run as a script,
prints them for the paper's cases: Table 1 (Case 1) with the thin layer's
upper bound at aspect ratios 10, 100 and 1000, and Case 4's K_pc.
"""
import argparse
import math


def inclined_interface_load(alpha_degrees):
    """Griffiths' Table 1: the axial stress P_ult / C_w that slides a column
    along a zero-thickness adhesive interface inclined at alpha,
    1 / (sin alpha cos alpha)."""
    a = math.radians(alpha_degrees)
    return 1 / (math.sin(a) * math.cos(a))


def inclined_layer_upper_bound(alpha_degrees, aspect_ratio):
    """An upper bound on the collapse stress of the body Case 1 actually
    models: a unit-width column crossed by a layer of finite thickness
    t = l / aspect_ratio (l = 1 / cos alpha, meshes/inclined-column.geo)
    between blocks that do not yield.

    The two blocks can slide rigidly along any straight plane that stays
    inside the layer. The plane from one face of the layer at one side of
    the column to the other face at the other side is inclined at alpha'
    with tan alpha' = tan alpha +- t / cos alpha = tan alpha +- 1 /
    (aspect_ratio cos^2 alpha); the sign that brings alpha' nearer 45
    degrees dissipates least. Its mechanism gives 1 / (sin alpha' cos
    alpha'), so the layer's exact collapse stress is at most that. At
    alpha = 10 or 80 degrees and aspect ratio 100 the bound is 5.2% below
    1 / (sin alpha cos alpha): a thick layer is weaker than the interface it
    models, whatever the solver.
    """
    a = math.radians(alpha_degrees)
    widening = 1 / (aspect_ratio * math.cos(a) ** 2)
    low, high = sorted((math.tan(a), math.tan(a) + (widening if alpha_degrees < 45 else -widening)))
    if low <= 1 <= high:
        return 2.0  # a plane at 45 degrees fits in the layer
    inclined = math.atan(high if high < 1 else low)
    return 1 / (math.sin(inclined) * math.cos(inclined))


def passive_rough_wall(adhesion_ratio):
    """The slip-line passive coefficient of a weightless Tresca soil
    against a wall with adhesion C_w = a c_u (Griffiths' Case 4):
    K_pc = 1 + asin(a) + sqrt(1 - a^2), 2 for a smooth wall."""
    a = adhesion_ratio
    return 1 + math.asin(a) + math.sqrt(1 - a * a)


def main():
    argparse.ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter).parse_args()
    print("Case 1, Table 1: P_ult / C_w, and the upper bound of a layer of aspect ratio")
    print("| alpha | 1/(sin a cos a) | layer bound, 10 | 100 | 1000 |")
    print("|---|---|---|---|---|")
    for alpha in (10, 20, 30, 40, 45, 50, 60, 70, 80):
        print("| %d | %.4f | %.4f | %.4f | %.4f |" % (
            alpha, inclined_interface_load(alpha),
            *(inclined_layer_upper_bound(alpha, r) for r in (10, 100, 1000))))
    print("\nCase 4: slip-line K_pc of a weightless Tresca soil")
    print("| C_w / c_u | K_pc |")
    print("|---|---|")
    for a in (0, 0.5, 1):
        print("| %g | %.4f |" % (a, passive_rough_wall(a)))


if __name__ == "__main__":
    main()
