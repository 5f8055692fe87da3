"""Keep the index of FORD's API reference to the public API (tools/ford.sh runs it).

The public API is what the umbrella module exports (the `public ::` statements of
src/wavyadhesion.f90). Internal modules (those the umbrella re-exports nothing from) carry
FORD's `display: none` in their module doc comment, so FORD documents the module but none
of its procedures or types. Some public modules also have public helpers for other
modules of the library (`set_error`, `check_params`, `dw_residual`, `append`, ...) that
the umbrella does not export: FORD cannot hide a single public procedure, so this script
drops them, and any procedure or type of a module still shown that the umbrella does not
export, from the index: the rows of lists/procedures.html and lists/types.html, and the
short lists on index.html (whose Modules box starts with the umbrella and shows only the
modules the umbrella re-exports from). Their own pages stay (a module page still links
them).

Usage: python3 tools/ford_public.py API_DIR SRC_DIR
"""
import pathlib
import re
import sys

ROW = re.compile(r"\s*<tr>\s*<td><a href='\.\./(?P<kind>proc|interface|type)/(?P<name>\w+)\.html'>"
                 r".*?</tr>", re.S)
BOX = re.compile(r"(<h3>(?P<title>Modules|Procedures|Derived Types)</h3>\s*<ul>)(?P<items>.*?)(</ul>)",
                 re.S)
LINK = re.compile(r"<a href='\.\./(\w+)/(\w+)\.html'>")
BOX_LEN = 10  # FORD's index shows the first ten of each list


def umbrella(src):
    """(public names, modules re-exported from) of src/wavyadhesion.f90, lower case."""
    text = (src / "wavyadhesion.f90").read_text().lower()
    text = re.sub(r"!.*", "", text)
    text = re.sub(r"&\s*\n\s*&?", " ", text)
    names = set()
    for stmt in re.findall(r"^\s*public\s*::(.*)$", text, re.M):
        names.update(n.strip() for n in stmt.split(",") if n.strip())
    modules = set(re.findall(r"^\s*use\s+(\w+)\s*,\s*only\s*:", text, re.M))
    return names, modules


def filter_list(page, public):
    text = page.read_text()
    kept, dropped = [], []

    def keep(m):
        (kept if m["name"] in public else dropped).append(m["name"])
        return m.group(0) if m["name"] in public else ""

    page.write_text(ROW.sub(keep, text))
    return kept, dropped


def main(api, src):
    public, modules = umbrella(src)
    procs, hidden_procs = filter_list(api / "lists" / "procedures.html", public)
    types, hidden_types = filter_list(api / "lists" / "types.html", public)
    mods = ["wavyadhesion"] + sorted(modules)
    boxes = {"Modules": ("module", mods), "Procedures": ("proc", procs),
             "Derived Types": ("type", types)}

    def box(m):
        kind, names = boxes[m["title"]]
        items = "".join(f"<li><a href='{kind}/{n}.html'>{n}</a></li>" for n in names[:BOX_LEN])
        return m.group(1) + items + m.group(4)

    index = api / "index.html"
    index.write_text(BOX.sub(box, index.read_text()))
    print(f"ford_public: index lists {len(procs)} procedures and {len(types)} types of the "
          f"umbrella; left out {len(hidden_procs)} procedures and {len(hidden_types)} types "
          "not exported")


if __name__ == "__main__":
    main(pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2]))
