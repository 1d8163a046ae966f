# Writes OUTPUT, a C++ file whose mjray::watch_page() returns the bytes of INPUT, so that the
# program serves the page without reading a file. Run by the build whenever INPUT changes:
#   cmake -DINPUT=page.html -DOUTPUT=watch_page.cpp -P embed_page.cmake
file(READ "${INPUT}" bytes HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "'\\\\x\\1'," bytes "${bytes}")
file(WRITE "${OUTPUT}"
  "// Generated from ${INPUT} by embed_page.cmake; edit the page, not this file.\n"
  "#include \"watch_page.h\"\n\n"
  "namespace mjray {\n\n"
  "namespace {\n"
  "constexpr char kPage[] = {${bytes}};\n"
  "}  // namespace\n\n"
  "std::string_view watch_page() { return {kPage, sizeof kPage}; }\n\n"
  "}  // namespace mjray\n")
