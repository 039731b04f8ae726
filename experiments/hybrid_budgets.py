#!/usr/bin/env python3
"""Per model and byte budget (a share of the original's bytes), the views in
which the hybrid level mode is on or below the best row of every other family
within the budget, and each family's mean best FLIP (docs/cost.md: The hybrid
level mode). Usage: hybrid_budgets.py results.csv"""
import collections
import csv
import sys

BUDGETS = (0.5, 0.25, 0.1, 0.05)


def family(row):
    return row["level_mode"]


def main(path):
    rows = list(csv.DictReader(open(path, newline="")))
    for model in sorted({r["model"] for r in rows}):
        ours = [r for r in rows if r["model"] == model]
        original = max(int(r["bytes"]) for r in ours if r["level"] == "0" and r["baseline_variant"] == "")
        families = sorted({family(r) for r in ours})
        views = sorted({r["view"] for r in ours})
        print(f"{model.split('/')[-1]}: original {original} bytes")
        for share in BUDGETS:
            wins, best_of = 0, collections.defaultdict(list)
            for view in views:
                best = {}
                for f in families:
                    flips = [float(r["flip"]) for r in ours if r["view"] == view and family(r) == f
                             and r["level"] != "0" and int(r["bytes"]) <= share * original]
                    if flips:
                        best[f] = min(flips)
                        best_of[f].append(best[f])
                others = [v for f, v in best.items() if f != "hybrid"]
                if "hybrid" in best and (not others or best["hybrid"] <= min(others)):
                    wins += 1
            mean = {f: sum(v) / len(v) for f, v in best_of.items()}
            means = ", ".join(f"{f} {m:.4f}" for f, m in sorted(mean.items()))
            # The README's targets: best in at least 90 % of the views, never 0.01 behind the best other family.
            others = [m for f, m in mean.items() if f != "hybrid"]
            gap = mean["hybrid"] - min(others) if "hybrid" in mean and others else float("nan")
            print(f"  within {share:.0%}: hybrid best in {wins} of {len(views)} views; mean best FLIP: {means}; "
                  f"hybrid behind the best other by {gap:+.4f}")


if __name__ == "__main__":
    main(sys.argv[1])
