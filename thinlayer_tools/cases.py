"""The benchmark cases' parameter files and mesh levels, defined once.

A level doubles the elements along the interface (or, for the footings,
refines the whole mesh once more); each level's geometry parameters are a
template with {ar} for the thin layer's aspect ratio and, in Case 1,
{alpha} for the interface's inclination. The benchmarks (benchmarks/) and
the report take their meshes from here, so a level means the same mesh
everywhere.
"""

PARAMETER_FILES = {
    "prandtl": "prm/prandtl-strip-footing.prm",
    "case1": "prm/case1-inclined-adhesive.prm",
    "case2": "prm/case2-strip-footing.prm",
    "case3": "prm/case3-circular-footing.prm",
    "case4": "prm/case4-rough-wall.prm",
}

_FOOTING = ("half_width=1, width=5, depth=3, aspect_ratio={ar}, n_footing=8, n_side=12, "
            "n_depth=10, interface_beyond_footing=1, refinement=%d")

MESH_LEVELS = {
    "prandtl": {
        1: "half_width=1, width=5, depth=3, n_footing=8, n_side=12, n_depth=12, growth=1.15",
        2: "half_width=1, width=5, depth=3, n_footing=16, n_side=24, n_depth=24, growth=1.07",
        3: "half_width=1, width=5, depth=3, n_footing=32, n_side=48, n_depth=48, growth=1.035",
    },
    "case1": {level: "alpha={alpha}, aspect_ratio={ar}, elements_along=%d, elements_block=%d"
              % (n, n) for level, n in ((1, 8), (2, 16), (3, 32))},
    "case2": {level: _FOOTING % level for level in (1, 2, 3)},
    "case3": {level: _FOOTING % level for level in (1, 2, 3)},
    "case4": {level: "wall_height=1, width=3, depth=2, aspect_ratio={ar}, n_wall=%d, "
              "n_below=%d, n_x=%d" % (10 * 2 ** (level - 1), 5 * 2 ** (level - 1),
                                      12 * 2 ** (level - 1)) for level in (1, 2, 3)},
}


def geometry(case, level, aspect_ratio="{ar}", alpha=30):
    """The geometry parameters (Mesh/Geometry parameters) of CASE at mesh
    LEVEL: with {ar} left in for the caller to fill unless ASPECT_RATIO is
    given; Case 1's interface at ALPHA degrees."""
    return MESH_LEVELS[case][level].format(ar=aspect_ratio, alpha=alpha)


# Prandtl's scene at growing meshes (cells: geometry parameters), each
# four times the cells of the one before at the same proportions, for the
# measurements of time and memory against size and ranks.
PRANDTL_SIZES = {
    128: "half_width=1, width=5, depth=3, n_footing=6, n_side=10, n_depth=8, growth=1.2",
    512: "half_width=1, width=5, depth=3, n_footing=12, n_side=20, n_depth=16, growth=1.1",
    2048: "half_width=1, width=5, depth=3, n_footing=24, n_side=40, n_depth=32, growth=1.05",
    8192: "half_width=1, width=5, depth=3, n_footing=48, n_side=80, n_depth=64, growth=1.025",
    32768: "half_width=1, width=5, depth=3, n_footing=96, n_side=160, n_depth=128, "
           "growth=1.0125",
    131072: "half_width=1, width=5, depth=3, n_footing=192, n_side=320, n_depth=256, "
            "growth=1.00625",
}

# The paper's method on seven fixed load steps to Prandtl's load: the same
# iterations on every mesh size and rank count, for timings.
PAPER_FIXED_STEPS = ("Solver/Tolerance=1e-3",
                     "Loading/Load increments=0.5, 0.3, 0.1, 0.05, 0.05, 0.02, 0.02",
                     "Loading/Collapse resolution=0")
