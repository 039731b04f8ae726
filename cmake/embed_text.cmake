# cmake -DINPUT=FILE -DOUTPUT=FILE.cpp -DNAME=symbol -P embed_text.cmake
# Writes a C++ file defining `const std::string_view boxlod::NAME` as INPUT's
# text (a raw string literal), so a program can write files shipped in the tree.
file(READ "${INPUT}" text)
string(FIND "${text}" ")embedded_text\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} holds the raw string's delimiter")
endif()
file(WRITE "${OUTPUT}.new" "// Generated from ${INPUT} by cmake/embed_text.cmake.\n#include <string_view>\n\nnamespace boxlod {\nextern const std::string_view ${NAME};\nconst std::string_view ${NAME} = R\"embedded_text(${text})embedded_text\";\n}  // namespace boxlod\n")
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.new")
