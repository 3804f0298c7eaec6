"""The reproduction report: the paper's tables and figures beside
thinlayer's, written by scripts/reproduce.sh into one self-contained HTML
page.

figures   matplotlib helpers every section shares (meshes from mesh.msh,
          load-displacement curves with only converged states, vector plots)
page      the HTML page: sections, tables, embedded images, verdicts
runs      the runs of a reproduction (summaries, sweeps, paths) as sections read them
case1, footings, case4, methods
          the sections: what the paper shows, what thinlayer computes, and
          the verdict, from the runs of thinlayer_tools/reproduce.py
"""
