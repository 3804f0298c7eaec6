#!/usr/bin/python3
"""One manual page per parameter section, generated from the program's own
documentation (``thinlayer --print-parameters``) so that it cannot drift.

    /usr/bin/python3 -m thinlayer_tools.manual.parameters THINLAYER DIRECTORY

Writes DIRECTORY/<section>.md for every top-level section the program
prints (nested sections, such as a phase's boundaries, on their parent's
page) and DIRECTORY/index.md, the list of them with the program's note on
repeated sections (replacing the placeholder the manual's sources hold).
Exits non-zero if the program prints no section.
"""
import argparse
import os
import re
import subprocess
import sys


def parse(text):
    """The header comment and the sections of a parameter file as
    ParameterHandler prints it: a list of (name, entries, subsections),
    each entry (name, default, documentation)."""
    header, root, stack, comment = [], ([], []), [], []
    current = root
    in_header = True
    for raw in text.splitlines():
        line = raw.strip()
        if in_header and line.startswith("#"):
            body = line.lstrip("#").strip()
            if body in ("Listing of Parameters", "---------------------"):
                continue
            header.append(body)
            continue
        in_header = False
        if line.startswith("#"):
            comment.append(line.lstrip("#").strip())
        elif line.startswith("subsection "):
            section = (line[len("subsection "):].strip(), [], [])
            current[1].append(section)
            stack.append(current)
            current = section[1:]
            comment = []
        elif line == "end":
            current = stack.pop()
            comment = []
        elif line.startswith("set "):
            name, _, default = line[len("set "):].partition("=")
            current[0].append((name.strip(), default.strip(), " ".join(comment)))
            comment = []
        elif not line:
            pass
        else:
            raise ValueError("unexpected line in the parameter listing: %r" % raw)
    return " ".join(header), root[1]


def slug(name):
    return re.sub(r"[^a-z0-9]+", "-", name.lower()).strip("-")


def literal(text):
    """@p text as inline code, empty shown as such."""
    if not text:
        return "*(empty)*"
    ticks = "``" if "`" in text else "`"
    return "%s%s%s" % (ticks, text, ticks)


def escape(text):
    return text.replace("|", "\\|").replace("*", "\\*").replace("_", "\\_").replace("<", "&lt;")


def entries_markdown(entries, level):
    lines = []
    for name, default, doc in entries:
        lines += ["%s `%s`" % ("#" * level, name), "",
                  "Default: %s" % literal(default), "", escape(doc) or "*(undocumented)*", ""]
    return lines


def page(section):
    name, entries, subsections = section
    lines = ["# `%s`" % name, "",
             "Generated from `thinlayer --print-parameters`: every entry of the section, "
             "its default and the program's own documentation of it.", "",
             "```text", "subsection %s" % name]
    lines += ["  set %s = %s" % (e, d) for e, d, _ in entries]
    lines += ["  subsection %s ... end" % s[0] for s in subsections]
    lines += ["end", "```", ""]
    lines += entries_markdown(entries, 2)
    for sub_name, sub_entries, _ in subsections:
        lines += ["## `%s` (inside `%s`)" % (sub_name, name), ""]
        lines += entries_markdown(sub_entries, 3)
    return "\n".join(lines).rstrip() + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("thinlayer", help="the thinlayer executable")
    parser.add_argument("directory", help="where the pages go")
    args = parser.parse_args()
    text = subprocess.run([args.thinlayer, "--print-parameters"], check=True,
                          capture_output=True, text=True).stdout
    header, sections = parse(text)
    if not sections:
        sys.exit("thinlayer_tools.manual.parameters: %s printed no parameter section"
                 % args.thinlayer)
    os.makedirs(args.directory, exist_ok=True)
    listing = ["# Parameters", "",
               "A scene's parameter file, section by section: one page per section "
               "that `thinlayer --print-parameters` prints, with every entry, its "
               "default and the program's own documentation of it (these pages are "
               "generated from it as the manual is built). "
               "`thinlayer FILE.prm --print-parameters` prints the same for one scene, "
               "with that scene's values.", "",
               escape(header), "",
               "| section | entries |", "|---|---|"]
    pages = []
    for section in sections:
        pages.append(slug(section[0]))
        with open(os.path.join(args.directory, pages[-1] + ".md"), "w") as f:
            f.write(page(section))
        listing.append("| [`%s`](%s.md) | %d |" % (section[0], pages[-1], len(section[1])))
    listing += ["", "```{toctree}", ":hidden:", ""] + pages + ["```"]
    with open(os.path.join(args.directory, "index.md"), "w") as f:
        f.write("\n".join(listing) + "\n")
    print("thinlayer_tools.manual.parameters: %d section pages in %s"
          % (len(sections), args.directory))


if __name__ == "__main__":
    main()
