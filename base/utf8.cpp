#include "base/utf8.h"

#include <cstdint>

namespace boxlod {

bool is_utf8(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = std::uint8_t(text[i]);
        const int length = lead < 0x80                    ? 1
                           : lead >= 0xC2 && lead <= 0xDF ? 2
                           : lead >= 0xE0 && lead <= 0xEF ? 3
                           : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                          : 0;
        if (length == 0 || i + std::size_t(length) > text.size()) return false;
        // The second byte's range (RFC 3629's table): E0 and F0 exclude overlongs, ED surrogates, F4 what
        // lies past U+10FFFF.
        std::uint8_t low = 0x80, high = 0xBF;
        if (lead == 0xE0) low = 0xA0;
        if (lead == 0xED) high = 0x9F;
        if (lead == 0xF0) low = 0x90;
        if (lead == 0xF4) high = 0x8F;
        for (int k = 1; k < length; ++k) {
            const auto byte = std::uint8_t(text[i + std::size_t(k)]);
            if (byte < (k == 1 ? low : 0x80) || byte > (k == 1 ? high : 0xBF)) return false;
        }
        i += std::size_t(length);
    }
    return true;
}

std::string utf8_or_latin1(std::string text) {
    if (is_utf8(text)) return text;
    std::string utf8;
    for (const char c : text) {
        const auto byte = std::uint8_t(c);
        if (byte < 0x80)
            utf8 += c;
        else {
            utf8 += char(0xC0 | byte >> 6);
            utf8 += char(0x80 | (byte & 0x3F));
        }
    }
    return utf8;
}

}  // namespace boxlod
