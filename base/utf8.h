// Text as UTF-8, which glTF's JSON, the CSVs and the key = value files all
// hold: names from legacy model files (an OBJ material "Terraind\xe6k" in
// Latin-1) are read as ISO-8859-1, whose bytes are its code points.
#pragma once
#include <string>
#include <string_view>

namespace boxlod {

// Well-formed UTF-8 (RFC 3629, section 4): no stray continuation byte, no
// overlong form, no surrogate, nothing past U+10FFFF.
bool is_utf8(std::string_view text);

// `text` where it is UTF-8, else its bytes read as ISO-8859-1.
std::string utf8_or_latin1(std::string text);

}  // namespace boxlod
