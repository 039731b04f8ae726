#include "toolkit/formats/xml_file_check.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <string>

using namespace boxlod;

namespace {

std::string problem(const std::string& bytes) {
    return test::input_error_of([&] { check_collada_file(bytes, "m.dae"); });
}

}  // namespace

TEST(XmlFileCheck, XmlNestedDeeperThanTheLimitIsRefused) {
    std::string deep = "<?xml version=\"1.0\"?><!-- <a><a><a> --><COLLADA>";
    for (int i = 0; i < 300; ++i) deep += "<node id=\"a>b\">";
    EXPECT_NE(problem(deep).find("XML elements nested more than 200 levels deep"), std::string::npos);
    std::string shallow = "<?xml version=\"1.0\"?><COLLADA>";
    for (int i = 0; i < 300; ++i) shallow += "<node/><node></node>";
    EXPECT_EQ(problem(shallow + "</COLLADA>"), "");
}

// assimp builds a COLLADA scene by recursion through the nodes a node instances: nodes that instance each
// other (by id or, failing that, by name), or themselves through a child, crashed it.
TEST(XmlFileCheck, ColladaNodesDoNotInstanceThemselves) {
    const auto scene = [](const std::string& nodes) {
        return "<?xml version=\"1.0\"?><COLLADA><library_nodes>" + nodes +
               "</library_nodes><library_visual_scenes><visual_scene id=\"s\"><node id=\"r\"><instance_node "
               "url=\"#a\"/></node></visual_scene></library_visual_scenes></COLLADA>";
    };
    const std::string b = "<node id=\"b\"><instance_geometry url=\"#g\"/></node>";
    EXPECT_EQ(
        problem(scene("<node id=\"a\"><instance_node url=\"#b\"/><instance_node url=\"#b\"/></node>" + b)),
        "");
    EXPECT_NE(problem(scene("<node id=\"a\"><instance_node url=\"#b\"/></node><node id=\"b\"><instance_node "
                            "url=\"#a\"/></node>"))
                  .find("<node id=\"a\">: nodes with the nodes they instance form a cycle"),
              std::string::npos);
    EXPECT_NE(problem(scene("<node id=\"a\"><node name=\"c\"><instance_node url=\"#a\"/></node></node>"))
                  .find("form a cycle"),
              std::string::npos);
    EXPECT_NE(
        problem(scene("<node id=\"a\"><instance_node url=\"#n\"/></node><node name=\"n\"><instance_node "
                      "url=\"#a\"/></node>"))
            .find("form a cycle"),
        std::string::npos);
    std::string chain = "<node id=\"a\"><instance_node url=\"#n1\"/></node>";
    for (int i = 1; i <= 300; ++i)
        chain += "<node id=\"n" + std::to_string(i) + "\"><instance_node url=\"#n" + std::to_string(i + 1) +
                 "\"/></node>";
    EXPECT_NE(problem(scene(chain)).find("nested more than 200 levels deep"), std::string::npos);
}

// assimp read a short array past its values (what it read differed run to run) and an accessor past its
// array; an array's count, the values it holds and its accessors' reach must agree.
TEST(XmlFileCheck, ColladaArraysHoldTheirCountAndAccessorsReadWithinThem) {
    const auto collada = [](const std::string& sources) {
        return "<?xml version=\"1.0\"?><COLLADA><![CDATA[ ' ]]>" + sources + "</COLLADA>";
    };
    const auto array = [](const std::string& count, const std::string& values) {
        return "<source id=\"p\"><float_array id=\"pa\" count=\"" + count + "\">" + values + "</float_array>";
    };
    const auto accessor = [](const std::string& attributes, int params) {
        std::string text = "<technique_common><accessor source=\"#pa\" " + attributes + ">";
        for (int p = 0; p < params; ++p) text += "<param name=\"X\" type=\"float\"/>";
        return text + "</accessor></technique_common></source>";
    };
    const std::string twelve = "0 0 0\n1 0 0 0 1 0 1 1 0";
    EXPECT_EQ(problem(collada(array("12", twelve) + accessor("count=\"4\" stride=\"3\"", 3))), "");
    const std::string past =
        "reads past its array #pa of 12 values (offset + (count - 1) x stride + its params)";
    EXPECT_NE(problem(collada(array("12", twelve) + accessor("count=\"5\" stride=\"3\"", 3))).find(past),
              std::string::npos);
    EXPECT_NE(problem(collada(array("12", twelve) + accessor("count=\"4\" stride=\"3\" offset=\"1\"", 3)))
                  .find(past),
              std::string::npos);
    // An accessor before its array, and one whose offset and count overflow when added.
    EXPECT_NE(problem(collada(accessor("count=\"1000000000\" stride=\"3\"", 3) + array("12", twelve)))
                  .find("reads past its array #pa"),
              std::string::npos);
    EXPECT_NE(problem(collada(array("12", twelve) +
                              accessor("count=\"9223372036854775808\" offset=\"9223372036854775808\"", 1)))
                  .find(past),
              std::string::npos);
    // Interleaved: the normals of a position-and-normal array of stride 6 reach its last value.
    EXPECT_EQ(problem(collada(array("24", twelve + " " + twelve) +
                              accessor("offset=\"3\" count=\"4\" stride=\"6\"", 3))),
              "");
    EXPECT_EQ(problem(collada(array("13", twelve) + accessor("count=\"4\" stride=\"3\"", 3))),
              "m.dae: byte 60 <float_array>: count 13 but 12 values");
    EXPECT_EQ(problem(collada(array("x", twelve))), "m.dae: byte 60 count: expected a count, got 'x'");
}
