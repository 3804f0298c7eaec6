"""The report as one self-contained HTML page: no file beside it, images
embedded as data URIs, no scripts, so that it opens in any browser and can
be mailed as it is."""
import html

# What a verdict says, and its colour.
VERDICTS = {
    "reproduced": ("reproduced", "#2e7d32"),
    "differs": ("differs", "#c62828"),
    "agrees": ("agrees with the closed form", "#2e7d32"),
    "disagrees": ("disagrees with the closed form", "#c62828"),
    "beyond": ("beyond the paper", "#1565c0"),
    # A displacement criterion against published ultimate loads that are
    # estimates, not closed forms (a laterally loaded pile).
    "mobilises": ("passes the published values", "#2e7d32"),
    "short": ("short of the published values", "#c62828"),
    "not run": ("not run in --quick", "#757575"),
}

STYLE = """
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em;
       color: #222; line-height: 1.4; }
h1 { font-size: 1.6em; } h2 { font-size: 1.25em; margin-top: 2em;
       border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.6em 0; font-size: 0.9em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; text-align: right; }
th { background: #f0f0f0; } td:first-child, th:first-child { text-align: left; }
.summary td, .summary th { text-align: left; }
.verdict { display: inline-block; color: white; padding: 0.1em 0.6em;
           border-radius: 0.3em; font-weight: bold; }
.paper { background: #f7f7f2; border-left: 4px solid #bbb; padding: 0.4em 0.8em; }
figure { margin: 0.8em 0; } figure img { max-width: 100%; border: 1px solid #ddd; }
figcaption { font-size: 0.85em; color: #555; }
"""


class Section:
    """One item of the report: a paper table or figure, or a check or study
    beyond the paper.

    paper: what the paper shows or says (quoted or read off); rows: a table,
    its first row the header; figures: (data URI, caption); verdict: a key
    of VERDICTS; why: the reason for the verdict; cost: what the runs took.
    """

    def __init__(self, key, title, paper, verdict, why, rows=(), figures=(), cost="",
                 paper_value="", our_value=""):
        if verdict not in VERDICTS:
            raise ValueError("unknown verdict " + verdict)
        self.key, self.title, self.paper, self.verdict, self.why = key, title, paper, verdict, why
        self.rows, self.figures, self.cost = list(rows), list(figures), cost
        self.paper_value, self.our_value = paper_value, our_value


def mesh_section(key, title, paper, description, figure, cells, layer):
    """A section for one of the paper's mesh drawings, which our copy of the
    paper does not hold: the mesh as meshed, checked against the paper's
    description of it (@p layer: the cells of the thin layer it describes,
    counted in the mesh; none means it differs)."""
    return Section(key, title, paper, "reproduced" if layer > 0 else "differs",
                   "The paper's drawing is not in our copy of its text; this mesh follows its "
                   "description: " + description + " The thin layer has %d cells." % layer,
                   figures=[figure], paper_value="mesh drawn",
                   our_value="same layout, %d cells, %d in the layer" % (cells, layer))


def badge(verdict):
    text, colour = VERDICTS[verdict]
    return '<span class="verdict" style="background:%s">%s</span>' % (colour, html.escape(text))


def table(rows, css_class=""):
    if not rows:
        return ""
    head = "".join("<th>%s</th>" % html.escape(str(c)) for c in rows[0])
    body = "".join("<tr>%s</tr>" % "".join("<td>%s</td>" % html.escape(str(c)) for c in row)
                   for row in rows[1:])
    return '<table class="%s"><tr>%s</tr>%s</table>' % (css_class, head, body)


def section_html(s):
    parts = ['<h2 id="%s">%s</h2>' % (s.key, html.escape(s.title)),
             '<p class="paper"><b>The paper:</b> %s</p>' % html.escape(s.paper),
             "<p>%s %s</p>" % (badge(s.verdict), html.escape(s.why))]
    parts.append(table(s.rows))
    for uri, caption in s.figures:
        parts.append('<figure><img src="%s" alt="%s"><figcaption>%s</figcaption></figure>'
                     % (uri, html.escape(caption), html.escape(caption)))
    if s.cost:
        parts.append("<p><small>Cost: %s</small></p>" % html.escape(s.cost))
    return "\n".join(parts)


def write(path, title, introduction, sections, footer):
    """The page: a summary table (item, paper, ours, verdict) linking to
    each section, then the sections."""
    summary = [["item", "the paper", "thinlayer", "verdict"]]
    links = []
    for s in sections:
        summary.append([s.title, s.paper_value, s.our_value, VERDICTS[s.verdict][0]])
        links.append('<a href="#%s">%s</a>' % (s.key, html.escape(s.title)))
    page = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
            "<title>%s</title><style>%s</style></head><body>" % (html.escape(title), STYLE),
            "<h1>%s</h1>" % html.escape(title)]
    page += ["<p>%s</p>" % html.escape(p) for p in introduction]
    page.append(table(summary, "summary"))
    page.append("<p>" + " &middot; ".join(links) + "</p>")
    page += [section_html(s) for s in sections]
    page.append("<hr><p><small>%s</small></p>" % html.escape(footer))
    page.append("</body></html>")
    with open(path, "w") as f:
        f.write("\n".join(page) + "\n")
