"""A run's results folder as pandas DataFrames."""
import json
import os


class Results:
    """The results folder of a run (`sanet run`, `Simulation.finish()`, a study's run):

        r = sanet.Results("results/around-the-wall")
        r.trajectories   # time, node, x, y, theta
        r.messages       # time_sent, from, to, delivery, bytes, time_received, delay, hops
        r.packets        # per node: IP packets sent, received, forwarded, dropped (with a network)
        r.metrics, r.transitions, r.log, r.routes
        r.summary        # summary.json as a dict
        r.trace("frames")  # a table of trace.sqlite: every radio frame sent and received

    Each table is read when first asked for, from the CSV file of the same name, with the
    file's own columns; a file the run did not write raises FileNotFoundError saying so."""

    TABLES = ("trajectories", "messages", "packets", "metrics", "transitions", "log", "routes", "min_distance")
    # trace.sqlite's tables (docs/trace.md), and their columns that hold node ids.
    TRACE = {"nodes": (), "obstacles": (), "poses": ("node",), "frames": ("node", "peer"),
             "messages": ("from_node", "to_node"), "routes": ("node", "destination", "next_hop"),
             "transitions": ("node",), "metrics": ("node",), "events": ("node",), "info": ()}

    def __init__(self, folder):
        if not os.path.isfile(os.path.join(folder, "summary.json")):
            raise FileNotFoundError(f"{folder} is not a results folder: it has no summary.json "
                                    "(sanet run writes one at the end of every run)")
        self.folder = folder
        self._tables = {}

    @property
    def summary(self):
        """summary.json as a dict."""
        with open(os.path.join(self.folder, "summary.json")) as f:
            return json.load(f)

    def table(self, name):
        """The results file NAME.csv as a DataFrame."""
        if name not in self._tables:
            import pandas
            path = os.path.join(self.folder, name + ".csv")
            if not os.path.isfile(path):
                raise FileNotFoundError(f"{path}: this run wrote no {name}.csv (files: "
                                        f"{', '.join(self.summary.get('files', []))})")
            self._tables[name] = pandas.read_csv(path, keep_default_na=False, na_values=[""])
        return self._tables[name]

    def trace(self, table):
        """A table of the run's trace.sqlite (written with outputs.trace, by default up to 200
        nodes) as a DataFrame, with its own columns; each column of node ids (node, peer, ...)
        is followed by the nodes' names (node_name, peer_name, ...)."""
        if table not in Results.TRACE:
            raise KeyError(f"trace.sqlite has no table {table!r}: its tables are {', '.join(Results.TRACE)}")
        path = os.path.join(self.folder, "trace.sqlite")
        if not os.path.isfile(path):
            raise FileNotFoundError(f"{path}: this run wrote no trace (outputs.trace is off, or the run has more "
                                    "than 200 nodes: set outputs.trace=true)")
        import sqlite3
        import pandas
        with sqlite3.connect(f"file:{path}?mode=ro", uri=True) as db:
            frame = pandas.read_sql_query(f"SELECT * FROM {table}", db)  # the name is one of TRACE's
            names = dict(db.execute("SELECT id, name FROM nodes").fetchall())
        for column in Results.TRACE[table]:
            at = frame.columns.get_loc(column) + 1
            frame.insert(at, column.replace("_node", "") + "_name" if column.endswith("_node") else column + "_name",
                         frame[column].map(names))
        return frame

    def __getattr__(self, name):
        if name in Results.TABLES:
            return self.table(name)
        raise AttributeError(f"Results has no {name!r}: tables are {', '.join(Results.TABLES)}, and summary")

    def __repr__(self):
        return f"sanet.Results({self.folder!r})"
