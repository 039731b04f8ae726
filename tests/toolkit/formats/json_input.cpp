#include "toolkit/formats/json_input.h"

#include "base/input_error.h"
#include "base/memory_budget.h"
#include "test_support.h"

#include <gtest/gtest.h>
#include <malloc.h>
#include <nlohmann/json.hpp>

#include <string>

using namespace boxlod;

namespace {

// `count` copies of `item` as a JSON array's elements.
std::string array_of(const std::string& item, int count) {
    std::string text = "[";
    for (int i = 0; i < count; ++i) text += (i ? "," : "") + item;
    return text + "]";
}

// The heap bytes nlohmann-json's tree of `text` holds, as glibc counts them (mmapped blocks too).
double heap_bytes_of_tree(const std::string& text) {
    const auto in_use = [] {
        const struct mallinfo2 info = mallinfo2();
        return double(info.uordblks + info.hblkhd);
    };
    const double before = in_use();
    const nlohmann::json tree = nlohmann::json::parse(text);
    return in_use() - before;
}

std::string problem(const std::string& text) {
    return test::input_error_of([&] { check_json_input(text, "f.json"); });
}

}  // namespace

TEST(JsonInput, TheTreeEstimateBoundsWhatTheTreeTakes) {
    std::string object = "{";
    for (int i = 0; i < 20000; ++i)
        object += (i ? ",\"" : "\"") + std::to_string(i) + "\":" + std::to_string(i);
    object += "}";
    for (const std::string& text :
         {array_of("[]", 100000), array_of("{}", 100000), array_of("1", 100000), array_of("\"\"", 100000),
          array_of("\"a string longer than fifteen bytes\"", 20000), array_of("[1.5,-2,3e4]", 30000), object,
          array_of("{\"a\":[[1,2],{\"b\":null}],\"c\":\"d\"}", 20000)}) {
        const double actual = heap_bytes_of_tree(text), estimate = json_tree_bytes(text);
        EXPECT_GE(estimate, actual) << text.substr(0, 40);
        EXPECT_LE(estimate, 4 * actual) << text.substr(0, 40);
    }
}

TEST(JsonInput, RefusesTextNestedTooDeepOrWhoseTreeExceedsTheBudget) {
    EXPECT_EQ(problem(array_of("[]", 1000)), "");
    const std::string deep = std::string(201, '[') + std::string(201, ']');
    EXPECT_EQ(problem(deep), "f.json: byte 200: JSON nested more than 200 levels deep");
    EXPECT_EQ(problem(std::string(200, '[') + std::string(200, ']')), "");
    // Brackets inside strings are text.
    EXPECT_EQ(problem("[\"" + std::string(300, '[') + "\\\"\"]"), "");
    test::MemoryBudgetScope restore;
    const std::string many = array_of("[]", 300000);  // 900 kB of text, a tree of some 30 MB
    set_memory_budget(10e6);
    EXPECT_NE(problem(many).find("f.json: its JSON, parsed, would need"), std::string::npos) << problem(many);
    set_memory_budget(100e6);
    EXPECT_EQ(problem(many), "");
}
