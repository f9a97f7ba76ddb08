"""sanet from Python: step a run, look at it and act on it between steps, and read results and
studies as pandas DataFrames (docs/python-module.md).

    import sanet
    with sanet.Simulation("scenarios/around-the-wall.yaml", seed=3, output="out") as sim:
        while sim.step(1.0):
            print(sim.now, sim.pose("robot"))
    print(sanet.Results("out").trajectories.head())

The classes a Python controller is given (Node, Params, Pose, RangeScan, Bearing, Route,
NetworkView, Message, ParamError, and the readings of Node.sensor: NodeBearing, BatteryReading,
ImuReading, FixReading, JointStatesReading, ImageReading) are here too (docs/python.md).
"""
from ._sanet import (BatteryReading, Bearing, FixReading, FolderRefused, ImageReading, ImuReading, JointStatesReading,
                     Message, NetworkView, Node, NodeBearing, ParamError, Params, Pose, RangeScan, ReportError, Route,
                     ScenarioError, Simulation, StudyReader)
from .results import Results
from .study import Study

__all__ = ["Simulation", "Results", "Study", "ScenarioError", "FolderRefused", "ReportError", "Node", "Params",
           "ParamError", "Pose", "RangeScan", "Bearing", "Route", "NetworkView", "Message", "NodeBearing",
           "BatteryReading", "ImuReading", "FixReading", "JointStatesReading", "ImageReading"]
