"""One chart program per study: run as `python3 -m thinlayer_tools.plots.NAME`
(scripts/run_studies.sh calls them after the runs)."""
