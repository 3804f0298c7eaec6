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
