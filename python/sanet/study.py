"""A study (`sanet sweep`) as pandas DataFrames, with `sanet report`'s numbers."""
import os
import sqlite3

from ._sanet import StudyReader


class Study:
    """A study's folder (or its study.sqlite):

        s = sanet.Study("results/aodv-sweep")
        s.parameters                 # the varied parameters
        s.runs                       # one row per run: name, seed, status, parameters, fingerprint, ...
        s.scalars                    # one row per run, one column per metric of its summary.json
        s.metrics                    # metric name -> how many runs have it
        s.report("ended_at_s", by="network.tx_power")   # sanet report's table: mean, 95 % CI, median

    report() computes what `sanet report` prints (the same code), one row per value of `by` and
    combination of the other parameters (`series`)."""

    def __init__(self, where):
        self.path = where if where.endswith(".sqlite") else os.path.join(where, "study.sqlite")
        if not os.path.isfile(self.path):
            raise FileNotFoundError(f"{where}: no study.sqlite (sanet sweep writes one in the study's folder)")
        self._reader = StudyReader(self.path)

    def _query(self, sql):
        import pandas
        with sqlite3.connect(f"file:{self.path}?mode=ro", uri=True) as db:
            return pandas.read_sql_query(sql, db)

    @property
    def parameters(self):
        return list(self._reader.parameters())

    @property
    def runs(self):
        return self._query("SELECT * FROM results ORDER BY run")

    @property
    def scalars(self):
        long = self._query("SELECT runs.name AS run, scalars.name AS metric, scalars.value FROM scalars "
                           "JOIN runs ON runs.id = scalars.run")
        return long.pivot(index="run", columns="metric", values="value")

    @property
    def metrics(self):
        return dict(self._reader.metrics())

    def report(self, metric, by=None):
        import pandas
        if by is None:  # as sanet report: the first varied parameter
            by = self.parameters[0] if self.parameters else ""
        rows = self._reader.summarise(metric, by)
        return pandas.DataFrame(rows, columns=["series", "value", "runs", "mean", "ci_low", "ci_high", "median"])

    def __repr__(self):
        return f"sanet.Study({self.path!r})"
