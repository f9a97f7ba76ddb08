// The process's one Python interpreter, embedded (Debian's libpython3, the interpreter of
// /usr/bin/python3, with its packages: numpy), started when the first Python controller is
// made and kept until the process ends. It is configured for repeatable runs: hash
// randomisation off (PYTHONHASHSEED=0), no signal handlers (sanet's own handle Ctrl-C), and
// Python's `random` and numpy's global generator seeded from each run's seed. Every call into
// Python happens on the thread that started it, which keeps the GIL.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pybind11 {
class error_already_set;
}

namespace sanet::python_controllers {

// Starts the interpreter once; later calls do nothing.
void EnsureInterpreter();

// Puts folders on sys.path (each once, after the standard library), for the modules of Python
// controllers.
void AddSearchPath(const std::vector<std::string>& folders);
// Whether `file` is in one of `folders`.
bool OnSearchPath(const std::string& file, const std::vector<std::string>& folders);

// Seeds `random` and numpy's global generator (numpy.random.seed: the seed modulo 2^32) from a
// run's seed. Before the interpreter starts, the seed is kept and applied when it does.
void SeedRun(std::uint64_t seed);

// A Python exception as Python prints it: "Traceback (most recent call last): File ..., line N
// ... Type: message", with the traceback's frames restored to the error so it can be raised again.
std::string TracebackText(pybind11::error_already_set& error);

}  // namespace sanet::python_controllers
