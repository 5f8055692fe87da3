#!/usr/bin/env python3
"""Summary of study/data/samples_check.txt (tools/reference/study_reference.py check): the library's
traced branches, folds, case switches and critical forces against mpmath (50 digits).

  python3 study/summarize_check.py [study/data/samples_check.txt]

Per model and kind: number of entries, worst error in c* and P* (the accuracy targets' measure: relative,
P* absolute where |P*| < 1e-3) and in a* (fold and switch locations, absolute), then every
entry worse than 1e-10 in P*/c* or 1e-10 in a*, and every entry the reference could not check.
"""
import sys
from collections import defaultdict


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "study/data/samples_check.txt"
    groups = defaultdict(list)
    bad, unchecked = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            w = line.split()
            tag, kind, model = w[0], w[1], w[2]
            al, mu, a, c, p = (float(x) for x in w[3:8])
            ea, ec, ep = (float(x) for x in w[11:14])
            note = " ".join(w[14:])
            sub = kind.split(":")[-1]
            if sub in ("snap",):
                groups[(model, tag, kind)].append((0.0, 0.0, 0.0))
                continue
            if note in ("reference-failed", "no-switch-bracket", "notfound"):
                unchecked.append(line.strip())
                continue
            groups[(model, tag, kind)].append((ea, ec, ep))
            e = max(ec, ep)
            if e > 1e-10 or ea > 1e-10:
                bad.append((max(e, ea), model, tag, kind, al, mu, a, c, p, ea, ec, ep, note))
    print("model tag    kind         n   max err c*  max err P*  max err a*")
    for key in sorted(groups):
        v = groups[key]
        print("%-5s %-6s %-10s %4d %11.2e %11.2e %11.2e" % (key[0], key[1], key[2], len(v),
              max(x[1] for x in v), max(x[2] for x in v), max(x[0] for x in v)))
    print("\nentries worse than 1e-10 (c*, P* or a*): %d" % len(bad))
    for b in sorted(bad, reverse=True):
        print("  %s %s %s alpha=%r mu=%r a*=%r c*=%r P*=%r: err a* %.2e c* %.2e P* %.2e %s" % b[1:])
    print("\nentries the reference could not check: %d" % len(unchecked))
    for u in unchecked:
        print("  " + u)


if __name__ == "__main__":
    main()
