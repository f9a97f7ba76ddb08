# Writes OUT, a C++ file defining sanet::view::PageFiles() with the contents of FILES (a
# comma-separated list of names in DIR) as raw string literals.
string(REPLACE "," ";" FILES "${FILES}")
set(code "// Generated from src/front/view/page by cmake/embed_files.cmake: do not edit.\n")
string(APPEND code "#include \"view/page_files.h\"\n\nnamespace sanet::view {\n\n")
string(APPEND code "const std::map<std::string, std::string>& PageFiles() {\n")
string(APPEND code "  static const std::map<std::string, std::string> files = {\n")
foreach(name ${FILES})
  file(READ ${DIR}/${name} content)
  string(APPEND code "      {\"${name}\", R\"sanet_page(${content})sanet_page\"},\n")
endforeach()
string(APPEND code "  };\n  return files;\n}\n\n}  // namespace sanet::view\n")
file(WRITE ${OUT} "${code}")
