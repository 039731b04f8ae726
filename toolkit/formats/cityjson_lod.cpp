// A geometry's LoD (toolkit/formats/cityjson_lod.h).
#include "toolkit/formats/cityjson_lod.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace boxlod {

using json = nlohmann::json;

std::string city_geometry_lod(const json& geometry) {
    auto lod = geometry.find("lod");
    if (lod == geometry.end()) return "";
    if (lod->is_string()) return lod->get<std::string>();
    if (!lod->is_number()) return "";
    std::ostringstream text;
    text << lod->get<double>();
    return text.str();
}

double city_lod_number(const std::string& lod) {
    // Digits with at most one inner dot ("2", "2.2"): not "0x2", "2e0" or "2.2.2".
    const std::size_t dot = lod.find('.');
    if (lod.empty() || lod.size() > 8 || lod.find_first_not_of("0123456789.") != std::string::npos ||
        dot == 0 || dot + 1 == lod.size() ||
        (dot != std::string::npos && lod.find('.', dot + 1) != std::string::npos))
        return -1;
    const double value = std::strtod(lod.c_str(), nullptr);
    return value <= 4 ? value : -1;
}

std::vector<std::size_t> city_geometries_of_lod(const json& geometries, const std::string& lod) {
    double finest = -INFINITY;
    for (const json& geometry : geometries)
        finest = std::max(finest, city_lod_number(city_geometry_lod(geometry)));
    // The LoD's geometries of one spelling: "2.2" and "2.20" of one object are two geometries of the
    // same LoD, which drawn together would draw it twice. The spelling asked if there is one, else the
    // first in the file.
    std::vector<std::size_t> candidates;
    std::string spelling;
    for (std::size_t g = 0; g < geometries.size(); ++g) {
        const std::string own = city_geometry_lod(geometries[g]);
        const bool same =
            own == lod || (city_lod_number(own) >= 0 && city_lod_number(own) == city_lod_number(lod));
        if (!(lod.empty() ? city_lod_number(own) == finest : same)) continue;
        candidates.push_back(g);
        if (spelling.empty() || own == lod) spelling = own;
    }
    std::vector<std::size_t> chosen;
    for (std::size_t g : candidates)
        if (city_geometry_lod(geometries[g]) == spelling) chosen.push_back(g);
    return chosen;
}

}  // namespace boxlod
