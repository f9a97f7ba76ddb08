// The viewer's page (src/front/view/page), compiled into the command by cmake/embed_files.cmake.
#pragma once

#include <map>
#include <string>

namespace sanet::view {

const std::map<std::string, std::string>& PageFiles();  // file name -> content

}  // namespace sanet::view
