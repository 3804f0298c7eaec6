# Sphinx configuration of the thinlayer manual (MyST Markdown).
#
# Only what Debian 12 ships is used: python3-sphinx (5.3), its alabaster
# theme, and python3-myst-parser (0.18). Nothing is fetched from the
# network. Build with warnings as errors:
#
#   /usr/bin/python3 -m sphinx -W --keep-going -b html doc /tmp/doc-html
#
# scripts/manual.sh builds the same pages with doc/parameters/ generated
# from `thinlayer --print-parameters`, and the Doxygen API reference
# beside them (api/, which Sphinx must not read).

project = "thinlayer"
author = "The thinlayer developers"
copyright = "the thinlayer developers, GNU LGPL 2.1 or later"

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
root_doc = "index"
exclude_patterns = ["_build", "api"]

# Anchors for headings down to level 3, so that pages can link to
# sections as [text](page.md#section-title).
myst_heading_anchors = 3

html_theme = "alabaster"
html_title = "thinlayer manual"
html_show_sourcelink = False
