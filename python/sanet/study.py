"""A study (`sanet sweep`) as pandas DataFrames, with `sanet report`'s numbers."""
import os
import sqlite3

from ._sanet import StudyReader


class Study:
    """A study's folder (or its study.sqlite):

        s = sanet.Study("results/data-mule")
        s.parameters                 # the varied parameters
        s.runs                       # one row per run: run_id, run_name, seed, status, parameters, ...
        s.scalars                    # one row per run (index run_id), a column per number of its summary.json
        s.metrics                    # metric -> runs that have it, per-node metrics folded over the nodes
        s.values("sum(metrics.m*.created.count)")       # one run's value per run_id (a pandas Series)
        s.report("delivery", by="speed",
                 derive={"delivery": "sum(metrics.mule.delivered.sum) / sum(metrics.m*.created.count)"})

    report() computes what `sanet report` prints (the same code), one row per value of `by` and
    combination of the other parameters (`series`). A run's id is `run_id` and its name
    `run_name` in every frame, so frames merge on `run_id` without surprises."""

    def __init__(self, where):
        self.path = where if where.endswith(".sqlite") else os.path.join(where, "study.sqlite")
        if not os.path.isfile(self.path):
            raise FileNotFoundError(f"{where}: no study.sqlite (sanet sweep writes one in the study's folder)")
        self._reader = StudyReader(self.path)
        self._derived = {}

    def _query(self, sql):
        import pandas
        with sqlite3.connect(f"file:{self.path}?mode=ro", uri=True) as db:
            return pandas.read_sql_query(sql, db)

    @property
    def parameters(self):
        return list(self._reader.parameters())

    @property
    def runs(self):
        runs = self._query("SELECT id AS run_id, name AS run_name, seed, status, fingerprint, wall_s, simulated_s, "
                           "ended_by, ended_at_s, folder, error FROM runs ORDER BY id")
        values = self._query("SELECT run AS run_id, name, coalesce(number, value) AS value FROM parameters")
        if not values.empty:
            wide = values.pivot(index="run_id", columns="name", values="value").reset_index()
            runs = runs.merge(wide, on="run_id", how="left")
        return runs

    @property
    def scalars(self):
        long = self._query("SELECT run AS run_id, name AS metric, value FROM scalars")
        return long.pivot(index="run_id", columns="metric", values="value")

    @property
    def metrics(self):
        """Metric -> completed runs that have it; per-node metrics folded over the nodes, named by
        the expression that folds them (`sum(metrics.*.created.count)`)."""
        return {name: runs for name, runs, _ in self._reader.metrics(False)}

    @property
    def per_node_metrics(self):
        return {name: runs for name, runs, _ in self._reader.metrics(True)}

    def derive(self, name, expression):
        """As `sanet report --derive NAME=EXPRESSION`: later calls and reports can use NAME."""
        self._reader.define(name, expression)
        self._derived[name] = expression

    def values(self, metric, derive=None):
        """A metric, expression or derived metric per completed run that has a value (index run_id)."""
        import pandas
        self._define(derive)
        values = self._reader.values(metric)
        return pandas.Series(values, name=metric, dtype=float).rename_axis("run_id")

    def report(self, metric, by=None, derive=None):
        """`sanet report -m METRIC --by BY`'s table: a row per value of `by` (numbers when every value
        is one) and combination of the other varied parameters (`series`, "" when there are none):
        runs, mean, 95 % interval (ci_low, ci_high) and median over the completed runs. `metric` is
        a name, an expression or a name of `derive` ({name: expression})."""
        import pandas
        self._define(derive)
        if by is None:  # as sanet report: the first varied parameter
            by = self.parameters[0] if self.parameters else ""
        rows = self._reader.summarise(metric, by)
        table = pandas.DataFrame(rows, columns=["series", "value", "runs", "mean", "ci_low", "ci_high", "median"])
        numbers = pandas.to_numeric(table["value"], errors="coerce")
        if len(table) and numbers.notna().all():
            table["value"] = numbers
        return table

    def _define(self, derive):
        for name, expression in (derive or {}).items():
            if self._derived.get(name) != expression:
                self.derive(name, expression)

    def __repr__(self):
        return f"sanet.Study({self.path!r})"
