// Where a CityJSON reader is, for its one-line refusals (docs/design.md: Errors).
#pragma once
#include <string>

namespace boxlod {

// Where a reader is: the file and a prefix naming the place ("line 3:
// CityObjects 'id': geometry 0: "); fail throws the InputError.
struct CityPlace {
    const std::string& file;
    std::string place;
    [[noreturn]] void fail(const std::string& what) const;
    CityPlace in(const std::string& step) const { return {file, place + step + ": "}; }
};

}  // namespace boxlod
