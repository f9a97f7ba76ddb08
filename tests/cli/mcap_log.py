"""A run's trace.mcap as the tests' independent reader (tests/mcap/decode_mcap.mjs, npm's
@mcap/core and ROS 2 message definitions) sees it: channels, counts, first and last messages,
messages out of time order."""
import json
import os
import subprocess


def decoded(source, modules, trace, save_dir=None):
    """The reader's account of `trace` (a dict); AssertionError if it fails or finds errors.
    With `save_dir`, large byte fields (pictures) are saved there."""
    command = ["node", os.path.join(source, "tests", "mcap", "decode_mcap.mjs"), modules, trace]
    done = subprocess.run(command + ([save_dir] if save_dir else []), capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise AssertionError(f"the MCAP reader failed on {trace}: {done.stderr}")
    log = json.loads(done.stdout)
    if log["errorCount"]:
        raise AssertionError(f"the MCAP reader found errors in {trace}: {log['errors']}")
    return log
