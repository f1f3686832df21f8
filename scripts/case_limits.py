#!/usr/bin/env python3
"""Time and peak memory of each case-file limit at its value (docs/limits.md): one paper case, changed to the
limit, run alone with `orthocheck report --cases DIR`. Build first: cargo build --release.

    python3 scripts/case_limits.py
"""
import os
import re
import shutil
import subprocess
import tempfile
import time

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
BIN = os.path.join(ROOT, "target", "release", "orthocheck")
TWENTY = "".join(f"      - name: r{i}\n        random_points: 20\n" for i in range(3))

# (what, case file, pattern, replacement)
LIMITS = [
    ("noise work, p3f3", "ex2_noise.yaml", r"trials: 10000", "trials: 166666"),
    ("noise work, p4f3", "ex4_four_points.yaml", r"trials: 10000", "trials: 250000"),
    ("noise work, p3f4 at 200 frames", "ex3_noise.yaml", r"frames: 4\n    trials: 10000",
     "frames: 200\n    trials: 2500"),
    ("census trials", "p4f3_uniqueness.yaml", r"trials: 10000", "trials: 100000"),
    ("census work, 200 frames", "p3f4_uniqueness.yaml", r"frames: 4\n    trials: 10000",
     "frames: 200\n    trials: 25000"),
    ("random-scene trials", "two_frames.yaml", r"trials: [0-9]+", "trials: 100000"),
    ("identity example trials", "identity_example.yaml", r"trials: [0-9]+", "trials: 100000"),
    ("identity census trials", "identity_census.yaml", r"trials: 200", "trials: 5000"),
    ("linearity runs", "linearity_price.yaml", r"      - name: \"random, 4 points\"\n(.*\n)*    trials: 200",
     TWENTY + "    deciding_body: \"§4 body\"\n    levels: [\"0.001\", \"0.01\", \"0.1\"]\n"
     "    deciding_levels: [\"0.001\", \"0.01\"]\n    alpha: \"0.05\"\n    trials: 666"),
    ("solution-count instances", "solution_count.yaml", r"instances: 12", "instances: 24"),
    ("rounding trials", "ex2_three_frames.yaml", r"rounding_trials: 20000", "rounding_trials: 1000000"),
    ("evaluation points", "twofold_squared.yaml", r"evaluation_points: [0-9]+", "evaluation_points: 10000"),
]


def main():
    cases = os.path.join(ROOT, "paper_cases")
    print("| limit | case | seconds | peak MiB |\n|---|---|---:|---:|")
    for what, name, pattern, replacement in LIMITS:
        with tempfile.TemporaryDirectory() as d:
            for f in os.listdir(cases):
                if not f.endswith(".yaml"):
                    shutil.copy(os.path.join(cases, f), d)
            text = open(os.path.join(cases, name), encoding="utf-8").read()
            changed = re.sub(pattern, lambda _: replacement, text, count=1)
            assert changed != text, f"{name}: {pattern} not found"
            open(os.path.join(d, name), "w", encoding="utf-8").write(changed)
            start = time.time()
            child = subprocess.Popen([BIN, "report", "--cases", d, "--out",
                                      os.path.join(d, "out")],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
            _, status, usage = os.wait4(child.pid, 0)
            took = time.time() - start
            assert os.waitstatus_to_exitcode(status) == 0, child.stderr.read().decode()
            # ru_maxrss: this child's peak resident set, in KiB
            print(f"| {what} | {name} | {took:.2f} | {usage.ru_maxrss / 1024:.0f} |")


if __name__ == "__main__":
    main()
