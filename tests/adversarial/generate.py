#!/usr/bin/env python3
"""Writes the committed adversarial corpus (tests/adversarial/{tracks,cases}) and its
manifest. Run from the repository root; the files are committed, this script documents how
they were made. Big inputs are not committed: the test builds them at run time."""
import os, re

ROOT = os.path.dirname(os.path.abspath(__file__))
manifest = []

def put(kind, name, text, cls, data=None):
    path = os.path.join(ROOT, kind, name)
    with open(path, "wb") as f:
        f.write(data if data is not None else text.encode("utf-8"))
    manifest.append(f"{kind}/{name}\t{cls}")

GOOD = [[(-0.195, -0.839), (-0.561, -0.433), (-0.078, -0.695)],
        [(-0.969, 0.462), (-0.387, 0.479), (-0.805, 0.145)],
        [(-0.748, -1.615), (-1.170, -1.700), (-0.552, -1.836)]]

def yaml_tracks(frames, names=("P", "Q", "R"), fmt=str):
    s = "points: [" + ", ".join(names) + "]\nframes:\n"
    for fr in frames:
        s += "  - [" + ", ".join(f"[{fmt(x)}, {fmt(y)}]" for x, y in fr) + "]\n"
    return s

def csv_tracks(frames, names=("P", "Q", "R"), fmt=str):
    s = "frame,point,x,y\n"
    for i, fr in enumerate(frames):
        for n, (x, y) in zip(names, fr):
            s += f"{i+1},{n},{fmt(x)},{fmt(y)}\n"
    return s

put("tracks", "good.yaml", yaml_tracks(GOOD), "ok")
put("tracks", "good.csv", csv_tracks(GOOD), "ok")
put("tracks", "bom.yaml", "\ufeff" + yaml_tracks(GOOD), "ok")
put("tracks", "bom.csv", "\ufeff" + csv_tracks(GOOD), "ok")
put("tracks", "crlf.yaml", yaml_tracks(GOOD).replace("\n", "\r\n"), "ok")
put("tracks", "crlf.csv", csv_tracks(GOOD).replace("\n", "\r\n"), "ok")
put("tracks", "negative_zero.yaml", yaml_tracks(GOOD).replace("-0.195", "-0.0"), "ok")
put("tracks", "negative_zero.csv", csv_tracks(GOOD).replace("-0.195", "-0.0"), "ok")
put("tracks", "big_1e308.yaml", yaml_tracks(GOOD, fmt=lambda v: f"{v}e308"), "ok-or-refused")
put("tracks", "big_1e308.csv", csv_tracks(GOOD, fmt=lambda v: f"{v}e308"), "ok-or-refused")
# Found by the tracks fuzzer (tests/suite/fuzz.rs): three points in four frames, one
# coordinate 1e308. Squared lengths overflow to inf, and nalgebra's SVD of a matrix holding
# inf looped without end (no iteration limit): p3f4's rank test hung for minutes.
put("tracks", "fuzz_p3f4_one_1e308.csv", """frame,point,x,y
1,Q′,3.4644830770184263,-8.10412328129776
1,Q,8.62317878496598,-5.083411630430485
1,P,-4.382773413942291,3.835323089568262
2,Q′,1.9913068788623491,1e308
2,Q,2.0911721627322017,2.603825010168203
2,P,-9.649126351148404,0.8203985246642481
3,Q′,9.496477476704335,0.6424993703514533
3,Q,-9.581021148785657,-7.96008099964605
3,P,-1.4861620824497572,0.12563017413675867
4,Q′,9.851483353071222,8.742709229935203
4,Q,-0.10377545394522408,-6.921699184285756
4,P,1.9811811321562922,5.947570551179307
""", "ok-or-refused")
put("tracks", "tiny_1e-300.yaml", yaml_tracks(GOOD, fmt=lambda v: f"{v}e-300"), "ok-or-refused")
put("tracks", "overflow_1e309.yaml", yaml_tracks(GOOD, fmt=lambda v: f"{v}e309"), "refused")
put("tracks", "overflow_1e309.csv", csv_tracks(GOOD, fmt=lambda v: f"{v}e309"), "refused")
# NaN and infinity spelt every way YAML 1.1/1.2 and CSV readers accept
for i, w in enumerate([".nan", ".NaN", ".NAN", "nan", "NaN", "NAN", ".inf", ".Inf", ".INF",
                       "-.inf", "-.Inf", "+.inf", "inf", "-inf", "Infinity", "-Infinity",
                       "infinity", "+inf", "1e999", "-1e999"]):
    t = yaml_tracks(GOOD).replace("-0.195", w, 1)
    put("tracks", f"nonfinite_{i:02}.yaml", t, "refused")
    c = csv_tracks(GOOD).replace("-0.195", w, 1)
    put("tracks", f"nonfinite_{i:02}.csv", c, "refused")
put("tracks", "quoted_nan.yaml", yaml_tracks(GOOD).replace("-0.195", '".nan"', 1), "refused")
put("tracks", "quoted.csv", csv_tracks(GOOD).replace("1,P,", '"1","P",', 1), "ok-or-refused")
put("tracks", "alias_bomb.yaml",
    "a: &a [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\nb: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
    "c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\nd: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c, *c]\n"
    "e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d, *d]\nf: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e, *e]\n"
    "g: &g [*f, *f, *f, *f, *f, *f, *f, *f, *f, *f]\npoints: [P, Q, R]\nframes: *g\n", "refused")
put("tracks", "alias_frames.yaml",
    "points: [P, Q, R]\nframes:\n  - &f [[0.1, 0.2], [0.3, 0.5], [0.7, 0.1]]\n  - *f\n  - *f\n", "ok-or-refused")
put("tracks", "deep_nesting.yaml", "points: [P, Q, R]\nframes: " + "[" * 5000 + "]" * 5000 + "\n", "refused")
put("tracks", "deep_map.yaml", "points: [P, Q, R]\nframes:\n" + "".join("  " * i + f"k{i}:\n" for i in range(300)), "refused")
put("tracks", "binary.yaml", "", "refused", data=bytes(range(256)) * 4)
put("tracks", "binary.csv", "", "refused", data=bytes((i * 37 + 11) % 256 for i in range(2048)))
put("tracks", "latin1.csv", "", "refused", data="frame,point,x,y\n1,Ü,1,2\n".encode("latin-1"))
put("tracks", "nul.yaml", yaml_tracks(GOOD).replace("Q", "Q\0"), "refused")
put("tracks", "empty.csv", "", "refused")
put("tracks", "header_only.csv", "frame,point,x,y\n", "refused")
put("tracks", "whitespace.yaml", "   \n\t\n", "refused")
put("tracks", "dup_points.yaml", yaml_tracks(GOOD, names=("P", "P", "Q")), "refused")
put("tracks", "empty_name.yaml", yaml_tracks(GOOD, names=("P", '""', "Q")), "refused")
put("tracks", "dup_points.csv", csv_tracks(GOOD, names=("P", "P", "Q")), "refused")
put("tracks", "empty_name.csv", csv_tracks(GOOD, names=("P", "", "Q")), "refused")
put("tracks", "dup_key.yaml", "points: [P, Q, R]\npoints: [P, Q, R]\nframes: []\n", "refused")
put("tracks", "two_docs.yaml", yaml_tracks(GOOD) + "---\n" + yaml_tracks(GOOD), "refused")
put("tracks", "ragged.yaml", yaml_tracks(GOOD).replace(", [-0.078, -0.695]]", "]", 1), "refused")
put("tracks", "triple.yaml", yaml_tracks(GOOD).replace("[-0.195, -0.839]", "[-0.195, -0.839, 1]"), "refused")
put("tracks", "string_coord.yaml", yaml_tracks(GOOD).replace("-0.195", "abc"), "refused")
put("tracks", "bool_coord.yaml", yaml_tracks(GOOD).replace("-0.195", "true"), "refused")
put("tracks", "null_coord.yaml", yaml_tracks(GOOD).replace("-0.195", "~"), "refused")
put("tracks", "hex_coord.yaml", yaml_tracks(GOOD).replace("-0.195", "0x10"), "refused")
put("tracks", "octal_coord.yaml", yaml_tracks(GOOD).replace("-0.195", "0o17"), "refused")
put("tracks", "quoted_coord.yaml", yaml_tracks(GOOD).replace("-0.195", '"-0.195"'), "refused")
put("tracks", "underscore.csv", csv_tracks(GOOD).replace("-0.195", "1_000"), "refused")
put("tracks", "one_frame.yaml", yaml_tracks(GOOD[:1]), "ok-or-refused")
put("tracks", "no_frames.yaml", "points: [P, Q, R]\nframes: []\n", "refused")
put("tracks", "no_points.yaml", "points: []\nframes: [[], [], []]\n", "refused")
put("tracks", "identical_frames.yaml", yaml_tracks([GOOD[0]] * 3), "ok-or-refused")
put("tracks", "all_zero.yaml", yaml_tracks([[(0, 0)] * 3] * 3), "ok-or-refused")
put("tracks", "collinear.yaml", yaml_tracks([[(0, 0), (1, 1), (2, 2)]] * 3), "ok-or-refused")
put("tracks", "coincident.csv", csv_tracks([[(1, 1)] * 3] * 3), "ok-or-refused")
put("tracks", "mixed_scale.yaml", yaml_tracks([[(1e-150, 1e150), (1, 2), (3, 1)]] + GOOD[1:]), "ok-or-refused")
put("tracks", "missing_row.csv", "\n".join(csv_tracks(GOOD).split("\n")[:-2]) + "\n", "refused")
put("tracks", "extra_column.csv", csv_tracks(GOOD).replace("1,P,-0.195,-0.839", "1,P,-0.195,-0.839,9"), "refused")
put("tracks", "frame_zero.csv", csv_tracks(GOOD).replace("\n1,", "\n0,"), "ok-or-refused")
put("tracks", "frame_huge.csv", csv_tracks(GOOD).replace("\n3,", "\n99999999999999999999,"), "ok-or-refused")
put("tracks", "negative_frame.csv", csv_tracks(GOOD).replace("\n2,", "\n-2,"), "ok-or-refused")
put("tracks", "unknown_field.yaml", yaml_tracks(GOOD) + "extra: 1\n", "refused")
put("tracks", "tab_indent.yaml", yaml_tracks(GOOD).replace("  -", "\t-"), "refused")
put("tracks", "long_name.yaml", yaml_tracks(GOOD, names=("P" * 10000, "Q", "R")), "ok-or-refused")
put("tracks", "unicode_names.yaml", yaml_tracks(GOOD, names=("Ω", "Q′", "点")), "ok")
put("tracks", "semicolon.csv", csv_tracks(GOOD).replace(",", ";"), "refused")
put("tracks", "spaces.csv", csv_tracks(GOOD).replace(",", ", "), "ok-or-refused")

# ---- case files: mutations of a valid small case
DOF = open(os.path.join(ROOT, "..", "..", "paper_cases", "dof_counts.yaml"), encoding="utf-8").read()
put("cases", "good_dof.yaml", DOF, "ok")
put("cases", "bom.yaml", "\ufeff" + DOF, "ok")
put("cases", "crlf.yaml", DOF.replace("\n", "\r\n"), "ok")
put("cases", "points_3000.yaml", DOF.replace("points: 3\n", "points: 3000\n", 1), "refused")
put("cases", "points_huge.yaml", DOF.replace("points: 3\n", "points: 18446744073709551615\n", 1), "refused")
put("cases", "points_overflow.yaml", DOF.replace("points: 3\n", "points: 99999999999999999999999\n", 1), "refused")
put("cases", "points_float.yaml", DOF.replace("points: 3\n", "points: 1e10\n", 1), "refused")
put("cases", "points_negative.yaml", DOF.replace("points: 3\n", "points: -3\n", 1), "refused")
put("cases", "points_nan.yaml", DOF.replace("points: 3\n", "points: .nan\n", 1), "refused")
put("cases", "printed_1e999.yaml", DOF.replace('unknowns: "18"', 'unknowns: "1e999"', 1), "refused")
put("cases", "printed_1e-999.yaml", DOF.replace('unknowns: "18"', 'unknowns: "1e-999"', 1), "refused")
put("cases", "printed_exp_huge.yaml", DOF.replace('unknowns: "18"', 'unknowns: "1e2147483647"', 1), "refused")
put("cases", "printed_nan.yaml", DOF.replace('unknowns: "18"', 'unknowns: "nan"', 1), "refused")
put("cases", "printed_inf.yaml", DOF.replace('unknowns: "18"', 'unknowns: ".inf"', 1), "refused")
put("cases", "printed_unquoted_float.yaml", DOF.replace('unknowns: "18"', 'unknowns: 18.0', 1), "ok-or-refused")
put("cases", "printed_negzero.yaml", DOF.replace('unknowns: "18"', 'unknowns: "-0.0"', 1), "ok")
put("cases", "id_empty.yaml", DOF.replace("id: dof-counts", 'id: ""', 1), "refused")
put("cases", "dup_key.yaml", DOF.replace("id: dof-counts", "id: dof-counts\nid: again", 1), "refused")
put("cases", "alias_bomb.yaml",
    "a: &a [x, x, x, x, x, x, x, x, x, x]\nb: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
    "c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\nd: &d [*c, *c, *c, *c, *c, *c, *c, *c, *c, *c]\n"
    "e: &e [*d, *d, *d, *d, *d, *d, *d, *d, *d, *d]\nf: &f [*e, *e, *e, *e, *e, *e, *e, *e, *e, *e]\n" + DOF, "refused")
put("cases", "deep_nesting.yaml", DOF + "extra: " + "[" * 5000 + "]" * 5000 + "\n", "refused")
put("cases", "binary.yaml", "", "refused", data=bytes(range(255, -1, -1)) * 8)
put("cases", "empty.yaml", "", "refused")
put("cases", "two_docs.yaml", DOF + "---\n" + DOF, "refused")
put("cases", "unknown_kind.yaml", DOF.replace("dof_count:", "dof_bogus:", 1), "refused")
put("cases", "points_quoted.yaml", DOF.replace("points: 3\n", 'points: "3"\n', 1), "refused")
put("cases", "points_single_quoted.yaml", DOF.replace("points: 3\n", "points: '3'\n", 1), "refused")
put("cases", "points_hex.yaml", DOF.replace("points: 3\n", "points: 0x3\n", 1), "refused")
put("cases", "points_separated.yaml", DOF.replace("points: 3\n", "points: 0_3\n", 1), "refused")
put("cases", "frames_zero.yaml", DOF.replace("frames: 3\n", "frames: 0\n", 1), "refused")

P3 = open(os.path.join(ROOT, "..", "..", "paper_cases", "ex2_three_frames.yaml"), encoding="utf-8").read()
put("cases", "good_p3f3.yaml", P3, "ok")
put("cases", "rounding_trials_1e10.yaml", re.sub(r"rounding_trials: \d+", "rounding_trials: 10000000000", P3), "refused")
put("cases", "rounding_trials_float.yaml", re.sub(r"rounding_trials: \d+", "rounding_trials: 1e10", P3), "refused")
put("cases", "rounding_trials_zero.yaml", re.sub(r"rounding_trials: \d+", "rounding_trials: 0", P3), "refused")
def nested_bomb(levels):
    """An alias bomb written inside one field: each level anchors a list of ten copies of the
    level below, so `levels` levels expand to 10^levels leaves."""
    text = '&a0 ["1", "1"]'
    for i in range(1, levels + 1):
        text = f"&a{i} [" + text + "".join(f", *a{i-1}" for _ in range(9)) + "]"
    return text
put("cases", "frames_alias_bomb.yaml", re.sub(r"(      frames:\n)((        .*\n)+)",
    lambda _: "      frames: [" + nested_bomb(7) + ", *a7, *a7]\n", P3, count=1), "refused")
wide = ('[&f [&p ["1", "1"]' + ", *p" * 9999 + "]" + ", *f" * 9999 + "]")
put("cases", "frames_alias_wide.yaml", re.sub(r"(      frames:\n)((        .*\n)+)",
    lambda _: "      frames: " + wide + "\n", P3, count=1), "refused")
put("cases", "frames_alias_small.yaml", re.sub(r"(      frames:\n)((        .*\n)+)",
    lambda _: "      frames: [" + nested_bomb(2) + ", *a2, *a2]\n", P3, count=1), "refused")
NOISE = open(os.path.join(ROOT, "..", "..", "paper_cases", "ex2_noise.yaml"), encoding="utf-8").read()
put("cases", "good_noise.yaml", NOISE, "ok")
put("cases", "noise_trials_quoted.yaml", re.sub(r"trials: \d+", 'trials: "200"', NOISE, count=1), "refused")
put("cases", "noise_trials_hex.yaml", re.sub(r"trials: \d+", "trials: 0xC8", NOISE, count=1), "refused")
put("cases", "noise_squares_contradict.yaml", NOISE.replace('lengths: ["2", "3", "4"]', 'lengths: ["2", "3", "4"]\n      squares: ["4", "9", "99"]', 1), "refused")
put("cases", "noise_trials_zero.yaml", re.sub(r"trials: \d+", "trials: 0", NOISE, count=1), "refused")
put("cases", "noise_trials_huge.yaml", re.sub(r"trials: \d+", "trials: 10000000000", NOISE, count=1), "refused")
put("cases", "noise_level_negative.yaml", NOISE.replace('level: "0.001"', 'level: "-0.1"', 1), "refused")
put("cases", "noise_level_huge.yaml", NOISE.replace('level: "0.001"', 'level: "1e308"', 1), "refused")
put("cases", "noise_level_1e999.yaml", NOISE.replace('level: "0.001"', 'level: "1e999"', 1), "refused")
put("cases", "noise_level_nan.yaml", NOISE.replace('level: "0.001"', 'level: ".nan"', 1), "refused")

AUD = open(os.path.join(ROOT, "..", "..", "paper_cases", "twofold_squared.yaml"), encoding="utf-8").read()
put("cases", "good_twofold.yaml", AUD, "ok")
m = re.search(r'      printed: >-\n((        .*\n)+)', AUD)
def formula(name, f):
    put("cases", name, AUD[:m.start(1)] + "        " + f + "\n" + AUD[m.end(1):], "refused")
formula("formula_nested_10000.yaml", "(" * 10000 + "x" + ")" * 10000)
formula("formula_nested_1000.yaml", "(" * 1000 + "x" + ")" * 1000)
formula("formula_unary_10000.yaml", "-" * 10000 + "x")
formula("formula_exponent_huge.yaml", "x^4294967295")
formula("formula_exponent_overflow.yaml", "x^99999999999999999999999")
formula("formula_expansion.yaml", "(a+b+c+d+e+f+g+h)^40")
formula("formula_tower.yaml", "((((x+1)^60)^60)^60)^60")
formula("formula_long.yaml", "+".join(["x"] * 30000))
put("cases", "evaluation_points_huge.yaml", re.sub(r"evaluation_points: \d+", "evaluation_points: 1000000000", AUD, count=1), "refused")
put("cases", "evaluation_points_zero.yaml", re.sub(r"evaluation_points: \d+", "evaluation_points: 0", AUD, count=1), "refused")

with open(os.path.join(ROOT, "manifest.tsv"), "w") as f:
    f.write("# input\texpected class (ok: loads; refused: a load error, exit 2; ok-or-refused: either, never a panic)\n")
    f.write("\n".join(manifest) + "\n")
print(len(manifest), "inputs")
