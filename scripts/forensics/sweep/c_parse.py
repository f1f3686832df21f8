"""Task C: parse the four \\put pictures of section 5.1 (lines 721-1162)."""
import re, numpy as np
SRC = __import__("os").environ["ORTHOCHECK_PAPER"]  # the paper's LaTeX source (not part of the project)
L = open(SRC).read().split("\n")
def pictures():
    pics = []; cur = None
    for n, line in enumerate(L, 1):
        if not (716 <= n <= 1162): continue
        if "\\begin{picture}" in line: cur = {"start": n, "segs": [], "labels": {}, "thin": [], "thick": []}; mode = None; last = None
        elif "\\end{picture}" in line: pics.append(cur); cur = None
        elif cur is not None:
            if "linewidth 0.2pt" in line: mode = "thin"
            elif "linewidth 1.0pt" in line: mode = "thick"
            elif "linewidth 0.4pt" in line: mode = "scene"
            m = re.search(r"\\put\(([-\d.]+),([-\d.]+)\)\{(.*)\}\s*$", line.strip())
            if not m: continue
            p = np.array([float(m.group(1)), float(m.group(2))]); what = m.group(3)
            if "moveto" in what: last = (p, n)
            elif "lineto" in what:
                seg = (last[0], p, last[1], n)
                (cur[mode] if mode in ("thin", "thick") else cur["segs"]).append(seg)
                last = (p, n)
            else:
                cur["labels"][what.strip("$").strip()] = (p, n)
    return pics
if __name__ == "__main__":
    for k, P in enumerate(pictures()):
        print("picture", k+1, "from line", P["start"], "labels", {a: tuple(b[0]) for a, b in P["labels"].items()})
        print("  scene segments:", [(tuple(s[0]), tuple(s[1]), s[2]) for s in P["segs"]])
