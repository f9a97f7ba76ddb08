#!/usr/bin/env python3
"""A study (`sanet sweep`) in pandas: its runs, every run's metrics as one table, and a metric
against the varied parameter with mean and 95 % confidence interval, the numbers of
`sanet report`.

  PYTHONPATH=build/python /usr/bin/python3 examples/python/load_study.py STUDY_FOLDER [METRIC]
  e.g. after: build/sanet sweep scenarios/around-the-wall.yaml --vary nodes.robot.controller.params.speed=0.3,0.6 \\
                  --seeds 1-3 -o results/speed-study
"""
import sys

import sanet


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    study = sanet.Study(sys.argv[1])
    metric = sys.argv[2] if len(sys.argv) > 2 else "ended_at_s"
    print("parameters:", ", ".join(study.parameters))
    print(study.runs[["run_name", "seed", "status", *study.parameters]].to_string(index=False))
    print()
    print(study.report(metric).to_string(index=False))


if __name__ == "__main__":
    main()
