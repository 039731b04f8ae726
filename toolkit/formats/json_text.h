// JSON text written straight into a string, compact, as nlohmann's dump()
// writes it (its number format; keys must come in the order its sorted
// objects print them, bytewise ascending, which is checked): what glTF files
// are written with (toolkit/formats/gltf_json.h), without building a tree.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace boxlod {

class JsonText {
public:
    std::string text;

    void begin_object();
    void end_object();
    void begin_array();
    void end_array();
    // A member's name; the value follows. Throws std::logic_error out of order.
    void key(std::string_view name);
    void string(std::string_view value);  // UTF-8 (else std::logic_error), escaped as nlohmann escapes
    void integer(std::int64_t value);
    // The shortest digits that read back; fixed for decimal exponents -4 < n <= 15, whole numbers with ".0";
    // null if not finite.
    void number(double value);
    void boolean(bool value);
    void null();
    void raw(std::string_view json);  // a value already written as JSON text

private:
    struct Level {
        bool object = false, empty = true;
        std::string last_key;
    };
    std::vector<Level> levels_;
    void open(char bracket, bool object);
    void close(bool object);
    void element();
    void quoted(std::string_view value);  // a string's text, escaped
};

}  // namespace boxlod
