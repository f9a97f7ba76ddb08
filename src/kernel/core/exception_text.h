// What the exception being handled says, whatever was thrown: a plugin may throw an int, a
// string or its own type, and the run must still name the cause.
#pragma once

#include <string>

namespace sanet {

// Call inside a catch block: what() of a std::exception, the text of a thrown string, or the
// type of anything else ("an exception of type int").
std::string CurrentExceptionText();

}  // namespace sanet
