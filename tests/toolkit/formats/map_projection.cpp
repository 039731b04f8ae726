#include "toolkit/formats/map_projection.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

// The RD New origin (x 155,000 m, y 463,000 m at Amersfoort) lies at
// 52.15517440 N, 5.38720621 E on WGS 84 (RDNAPTRANS 2018's published point);
// PROJ's Helmert fit is within a metre, 1e-5 degrees. The grid's north is
// true north on its central meridian.
TEST(MapProjection, TheRdOriginLiesAtAmersfoort) {
    // EPSG 7415's NAP heights are above the geoid, there 43.30 m above the ellipsoid by EGM96's
    // grid; EPSG 28992 names no heights: the file's are kept.
    const struct {
        const char* system;
        double height;
        bool by_geoid;
    } systems[] = {{"EPSG:28992", 7, false}, {"https://www.opengis.net/def/crs/EPSG/0/7415", 50.30, true}};
    for (const auto& [system, height, by_geoid] : systems) {
        const MapPlacement placed = place_on_earth(system, {155000, 463000, 7}, "rd.city.json");
        EXPECT_NEAR(placed.at.latitude_degrees, 52.15517440, 1e-5) << system;
        EXPECT_NEAR(placed.at.longitude_degrees, 5.38720621, 1e-5) << system;
        EXPECT_NEAR(placed.at.height, height, 0.01) << system;
        EXPECT_NEAR(placed.at.heading_degrees, 0, 1e-3) << system;
        // EPSG 7415 by its horizontal part, not PROJ's ballpark for the compound (110 m off).
        EXPECT_EQ(placed.operation.find("allpark"), std::string::npos) << placed.operation;
        EXPECT_NE(placed.operation.find("Amersfoort to WGS 84"), std::string::npos) << placed.operation;
        EXPECT_EQ(placed.operation.find("NAP height by EGM96's geoid") != std::string::npos, by_geoid)
            << placed.operation;
    }
}

// In Rotterdam, 0.93 degrees west of the central meridian, the grid's north
// turns west by the meridian convergence, about (lambda - lambda0) sin(phi).
TEST(MapProjection, TheGridsNorthTurnsAwayFromTheCentralMeridian) {
    const MapPlacement placed = place_on_earth("EPSG:28992", {91000, 437000, 0}, "rotterdam.city.json");
    const double convergence =
        (placed.at.longitude_degrees - 5.38763888889) * std::sin(placed.at.latitude_degrees * M_PI / 180);
    EXPECT_LT(placed.at.heading_degrees, -0.5);
    EXPECT_NEAR(placed.at.heading_degrees, convergence, 0.01);
}

// Far outside where it is meant for a projection still gives a place: RD New at 9e8 m was placed at
// 51.6 S, 176 W, Web Mercator at 1e11 m at the pole.
TEST(MapProjection, AnOriginOutsideWhereTheSystemIsDefinedIsRefused) {
    for (const auto& [system, far] : {std::pair{"EPSG:7415", 9e8}, std::pair{"EPSG:3857", 1e11}}) {
        const std::string error = test::input_error_of([&] {
            place_on_earth(system, {far, far, 0}, "far.city.json");
        });
        EXPECT_NE(error.find("lies outside where it is meant for (at longitude"), std::string::npos)
            << system << ": " << error;
    }
    EXPECT_EQ(test::input_error_of([] { place_on_earth("EPSG:3857", {1e6, 6e6, 0}, "near.city.json"); }), "");
    // A degree beyond a UTM zone's edge: still where the zone's grid is used.
    EXPECT_EQ(test::input_error_of([] {
                  place_on_earth("EPSG:32632", {200000, 5400000, 0}, "edge.city.json");
              }),
              "");
}

TEST(MapProjection, AnUnknownSystemIsRefusedNamingTheFile) {
    const std::string error = test::input_error_of([] {
        place_on_earth("EPSG:999999", {0, 0, 0}, "district.city.json");
    });
    EXPECT_NE(error.find("district.city.json: reference system 'EPSG:999999'"), std::string::npos) << error;
    EXPECT_NE(error.find("--latitude"), std::string::npos) << error;
    EXPECT_NE(test::input_error_of([] { place_on_earth("not a system", {0, 0, 0}, "a.city.json"); }), "");
    // The model's coordinates are metres east and north: degrees, geocentric metres and feet are refused.
    // ... and so are grids whose axes point south and west (Krovak, EPSG 2065).
    for (const char* other : {"EPSG:4326", "EPSG:4978", "EPSG:2263", "EPSG:2065"})
        EXPECT_NE(test::input_error_of([&] {
                      place_on_earth(other, {1, 1, 0}, "a.city.json");
                  }).find(std::string("reference system '") + other + "'"),
                  std::string::npos)
            << other;
    // ... and heights in feet (RD New with NAVD88's heights in US feet).
    EXPECT_NE(test::input_error_of([] {
                  place_on_earth("EPSG:28992+6360", {1, 1, 0}, "a.city.json");
              }).find("its heights are not metres up"),
              std::string::npos);
    // ... and depths (RD New with depths below mean sea level).
    EXPECT_NE(test::input_error_of([] {
                  place_on_earth("EPSG:28992+5715", {1, 1, 0}, "a.city.json");
              }).find("its heights are not metres up"),
              std::string::npos);
    // One line, whatever the file names.
    const std::string two_lines = test::input_error_of([] {
        place_on_earth("EPSG:1\nx", {0, 0, 0}, "a.city.json");
    });
    EXPECT_EQ(two_lines.find('\n'), std::string::npos) << two_lines;
}
