#!/usr/bin/python3
"""Truth checked: the library's floors form no cycle. Every folder of
include/thinlayer/ and its mirror in source/ may include the folders below
it and never one that includes it back (the manual's architecture page):
a pair of folders that include each other, or a longer cycle, fails the
test, naming the files that close it.

    /usr/bin/python3 tests/unit/floors.py TOP
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*<thinlayer/([a-z_]+)/([a-z_]+\.h)>', re.M)


def edges(top):
    """{(floor, used floor): [file, ...]} over include/ and source/."""
    found = {}
    for root in (os.path.join(top, "include", "thinlayer"), os.path.join(top, "source")):
        for floor in sorted(os.listdir(root)):
            folder = os.path.join(root, floor)
            if not os.path.isdir(folder):
                continue
            for name in sorted(os.listdir(folder)):
                with open(os.path.join(folder, name)) as f:
                    for used, _ in INCLUDE.findall(f.read()):
                        if used != floor:
                            found.setdefault((floor, used), []).append(
                                os.path.relpath(os.path.join(folder, name), top))
    return found


def cycle(graph):
    """A cycle of floors in @p graph ({floor: {used}}), or None."""
    state, path = {}, []

    def visit(node):
        state[node] = "open"
        path.append(node)
        for used in sorted(graph.get(node, ())):
            if state.get(used) == "open":
                return path[path.index(used):] + [used]
            if used not in state:
                found = visit(used)
                if found:
                    return found
        state[node] = "done"
        path.pop()
        return None

    for node in sorted(graph):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def main(top):
    found = edges(top)
    graph = {}
    for floor, used in found:
        graph.setdefault(floor, set()).add(used)
    print("floors: %d, pairs in which one includes the other: %d"
          % (len({f for pair in found for f in pair}), len(found)))
    loop = cycle(graph)
    if loop is None:
        print("no cycle: yes")
        return 0
    print("no cycle: NO, %s" % " -> ".join(loop))
    for a, b in zip(loop, loop[1:]):
        print("  %s includes %s in %s" % (a, b, ", ".join(found[(a, b)])))
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else
                  os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")))
