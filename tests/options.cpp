#include "toolkit/cli/options.h"

#include "renderer/input_error.h"

#include <gtest/gtest.h>

using namespace boxlod;

namespace {
Command render_like() {
    return {"render", "MODEL", "Render.", {{"output", "FILE", "output", 'o'}, {"width", "W", "width"}, {"axes", "", "axes"}}, 1, 1};
}
}  // namespace

TEST(Options, ParsesLongShortInlineAndFlags) {
    Arguments a = parse_arguments(render_like(), {"m.gltf", "-o", "x.png", "--width=640", "--axes"});
    EXPECT_EQ(a.positionals, std::vector<std::string>{"m.gltf"});
    EXPECT_EQ(a.text("output"), "x.png");
    EXPECT_EQ(a.integer("width", 0), 640);
    EXPECT_TRUE(a.has("axes"));
    EXPECT_EQ(a.number("height", 7.5), 7.5);
}

TEST(Options, RejectsWhatItDoesNotKnow) {
    EXPECT_THROW(parse_arguments(render_like(), {"m.gltf", "--bogus"}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {"m.gltf", "--width"}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {"a", "b"}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {"a", "--axes=1"}), InputError);
    Arguments a = parse_arguments(render_like(), {"m", "--width", "wide"});
    EXPECT_THROW(a.integer("width", 0), InputError);
    EXPECT_THROW(a.number("width", 0), InputError);
}

TEST(Options, HelpListsEveryOption) {
    std::string help = help_text(render_like());
    for (const char* text : {"usage: boxlod render MODEL", "-o, --output FILE", "--width W", "--axes", "--help"})
        EXPECT_NE(help.find(text), std::string::npos) << text;
}
