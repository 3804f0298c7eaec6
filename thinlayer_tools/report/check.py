#!/usr/bin/python3
"""Check a reproduction report the way a reader gets it: in a browser.

    /usr/bin/python3 -m thinlayer_tools.report.check REPORT.html [--screenshot PNG]

Fails (exit 1, naming what is wrong) unless
- the page holds a section for each of the paper's items (Table 1,
  Figures 2 to 12, Table 2) and a verdict in each;
- it is self-contained: every image an embedded PNG that decodes, nothing
  loaded from elsewhere (no http:, no file beside it);
- no table cell reads nan or inf;
- headless Chromium renders it: its screenshot (default beside the report)
  is the page's width, and not blank (several colours, dark text on the
  light background).
"""
import argparse
import base64
import html.parser
import io
import os
import re
import subprocess
import sys
import tempfile

import matplotlib.image

ITEMS = ["table1", "figure2", "figure3", "figure4", "figure5", "figure6", "figure7",
         "figure9", "figure10", "figure11", "figure12"]


class Reader(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.images, self.references, self.cells, self.verdicts = [], [], [], [], 0
        self.in_cell = False

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if "id" in attrs:
            self.ids.append(attrs["id"])
        if tag == "img":
            self.images.append(attrs.get("src", ""))
        for key in ("src", "href"):
            value = attrs.get(key, "")
            if value and not value.startswith(("data:", "#")):
                self.references.append(value)
        if tag == "span" and attrs.get("class") == "verdict":
            self.verdicts += 1
        self.in_cell = tag in ("td", "th")

    def handle_data(self, data):
        if self.in_cell:
            self.cells.append(data.strip())

    def handle_endtag(self, tag):
        self.in_cell = False


def problems(path, screenshot):
    found = []
    with open(path) as f:
        text = f.read()
    reader = Reader()
    reader.feed(text)
    missing = [item for item in ITEMS if item not in reader.ids]
    if missing:
        found.append("no section for " + ", ".join(missing))
    if reader.verdicts < len(ITEMS):
        found.append("%d verdicts for %d paper items" % (reader.verdicts, len(ITEMS)))
    if reader.references:
        found.append("not self-contained: " + ", ".join(reader.references[:5]))
    for k, src in enumerate(reader.images):
        if not src.startswith("data:image/png;base64,"):
            found.append("image %d is not an embedded PNG" % k)
            continue
        try:
            image = matplotlib.image.imread(io.BytesIO(base64.b64decode(src.split(",", 1)[1])),
                                            format="png")
        except Exception as error:  # noqa: BLE001 (any decoding error is the finding)
            found.append("image %d does not decode: %s" % (k, error))
            continue
        if image.shape[0] < 100 or image.shape[1] < 100:
            found.append("image %d is %dx%d pixels" % (k, image.shape[1], image.shape[0]))
    bad = [c for c in reader.cells if re.search(r"\b(nan|inf)\b", c, re.IGNORECASE)]
    if bad:
        found.append("table cells read nan/inf: " + "; ".join(bad[:5]))
    found += render(path, screenshot)
    return found


def render(path, screenshot):
    """Headless Chromium's screenshot of the page, checked for content."""
    width, height = 1200, 2400
    with tempfile.TemporaryDirectory() as profile:
        done = subprocess.run(["chromium", "--headless", "--no-sandbox", "--disable-gpu",
                               "--hide-scrollbars", "--user-data-dir=" + profile,
                               "--window-size=%d,%d" % (width, height),
                               "--screenshot=" + screenshot, "file://" + os.path.abspath(path)],
                              capture_output=True, text=True, timeout=120)
    if done.returncode != 0 or not os.path.exists(screenshot):
        return ["chromium could not render the page: " + done.stderr.strip()[-500:]]
    image = matplotlib.image.imread(screenshot)
    if image.shape[1] != width:
        return ["the screenshot is %d pixels wide, not %d" % (image.shape[1], width)]
    grey = image[:, :, :3].mean(axis=2)
    dark = (grey < 0.3).mean()
    # Colours quantised to 8 levels a channel: a page of text and tables
    # alone (black text, grey rules, blue links, the verdicts' green, red and
    # blue) has about 16 when no figure falls in the screenshot; a failed
    # render (a white or an error page) has one or two.
    colours = len({tuple((pixel * 8).astype(int)) for pixel in image[::7, ::7, :3].reshape(-1, 3)})
    if dark < 0.002 or colours < 8:
        return ["the screenshot looks blank (%.2f%% dark pixels, %d colours)" % (100 * dark, colours)]
    return []


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("report", help="the report.html to check")
    parser.add_argument("--screenshot", help="where the screenshot goes (default: beside the "
                        "report, screenshot.png)")
    arguments = parser.parse_args()
    screenshot = arguments.screenshot or os.path.join(os.path.dirname(
        os.path.abspath(arguments.report)), "screenshot.png")
    found = problems(arguments.report, screenshot)
    for problem in found:
        print("thinlayer_tools.report.check: %s: %s" % (arguments.report, problem), file=sys.stderr)
    if found:
        sys.exit(1)
    print("thinlayer_tools.report.check: %s renders in Chromium (%s) and holds every paper item"
          % (arguments.report, screenshot))


if __name__ == "__main__":
    main()
