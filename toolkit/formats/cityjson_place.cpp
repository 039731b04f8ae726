#include "toolkit/formats/cityjson_place.h"

#include "base/input_error.h"

namespace boxlod {

void CityPlace::fail(const std::string& what) const {
    std::string where = place;
    while (!where.empty() && (where.back() == ' ' || where.back() == ':')) where.pop_back();
    throw_input_error(file, where, what);
}

}  // namespace boxlod
