#include "base/command_line.h"

#include "base/input_error.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace boxlod;

namespace {
Command render_like() {
    return {"render",
            "MODEL",
            "Render.",
            {{"output", "FILE", "output", {}, "", 'o'},
             {"width", "W", "width", NumberRange{1, 16384}},
             {"height", "H", "height", NumberRange{1, 16384}},
             {"name", "N", "a name"},
             {"axes", "", "axes"}},
            1,
            1};
}

std::string message_of(const std::vector<std::string>& words) {
    return test::input_error_of([&] { parse_arguments(render_like(), words); });
}
}  // namespace

TEST(CommandLine, ParsesLongShortInlineAndFlags) {
    Arguments a = parse_arguments(render_like(), {"m.gltf", "-o", "x.png", "--width=640", "--axes"});
    EXPECT_EQ(a.positionals, std::vector<std::string>{"m.gltf"});
    EXPECT_EQ(a.text("output"), "x.png");
    EXPECT_EQ(a.integer("width", 0), 640);
    EXPECT_TRUE(a.has("axes"));
    EXPECT_EQ(a.number("height", 7.5), 7.5);
}

TEST(CommandLine, RejectsWhatItDoesNotKnow) {
    EXPECT_THROW(parse_arguments(render_like(), {"m.gltf", "--bogus"}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {"m.gltf", "--width"}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {"a", "b"}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {"a", "--axes=1"}), InputError);
    EXPECT_THROW(parse_arguments(render_like(), {"m", "--width", "wide"}), InputError);
    Arguments a = parse_arguments(render_like(), {"m", "--width", "2.5"});
    EXPECT_THROW(a.integer("width", 0), InputError);
}

// An empty value is a mistake (an unset shell variable), not an absent option.
TEST(CommandLine, AnEmptyValueIsRefused) {
    EXPECT_EQ(message_of({"m", "--name", ""}), "boxlod render: --name needs a value N, got ''");
    EXPECT_EQ(message_of({"m", "--name="}), "boxlod render: --name needs a value N, got ''");
    EXPECT_EQ(message_of({"m", "-o", ""}), "boxlod render: --output needs a value FILE, got ''");
}

TEST(CommandLine, NumbersOutsideTheirDeclaredRangeAreRefusedWhileParsing) {
    EXPECT_EQ(message_of({"m", "--width", "100000"}),
              "boxlod render: --width: expected a number in [1, 16384], got '100000'");
    EXPECT_EQ(message_of({"m", "--height=0"}),
              "boxlod render: --height: expected a number in [1, 16384], got '0'");
    EXPECT_NE(message_of({"m", "--width", "1e39"}), "");
    EXPECT_NE(message_of({"m", "--width", "nan"}), "");
    EXPECT_NE(message_of({"m", "--width", "inf"}), "");
    EXPECT_EQ(message_of({"m", "--width", "16384"}), "");
}

TEST(CommandLine, ReadingANumberFromAnOptionWithoutARangeIsAProgrammingError) {
    Arguments a = parse_arguments(render_like(), {"m", "--name", "5"});
    EXPECT_THROW(a.number("name", 0), std::logic_error);
    EXPECT_THROW(a.integer("name", 0), std::logic_error);
    EXPECT_THROW(a.number("undeclared", 0), std::logic_error);
}

TEST(CommandLine, HelpListsEveryOption) {
    std::string help = help_text(render_like());
    for (const char* text :
         {"usage: boxlod render MODEL", "-o, --output FILE", "--width W", "--axes", "--help"})
        EXPECT_NE(help.find(text), std::string::npos) << text;
}

TEST(CommandLine, HelpNamesTheRangeOfEveryNumericOption) {
    Command command = render_like();
    command.options[2].help = "height (default: the model's)";
    std::string help = help_text(command);
    EXPECT_NE(help.find("width (range [1, 16384])\n"), std::string::npos) << help;
    EXPECT_NE(help.find("height (default: the model's; range [1, 16384])\n"), std::string::npos) << help;
    EXPECT_NE(help.find("a name\n"), std::string::npos) << help;  // no range, nothing added
}

// A default is written once, in the option's declaration: the help shows it,
// an option not given reads as it, and reading it with another fallback (or a
// number with neither) is a programming error.
TEST(CommandLine, ADeclaredDefaultIsShownAndReadFromItsDeclarationOnly) {
    Command command = render_like();
    command.options[1].default_value = "1024";
    command.options[3].default_value = "boxlod";
    const std::string help = help_text(command);
    EXPECT_NE(help.find("width (default 1024; range [1, 16384])\n"), std::string::npos) << help;
    EXPECT_NE(help.find("a name (default boxlod)\n"), std::string::npos) << help;
    const Arguments absent = parse_arguments(command, {"m"});
    EXPECT_EQ(absent.integer("width"), 1024);
    EXPECT_EQ(absent.number("width"), 1024);
    EXPECT_EQ(absent.text("name"), "boxlod");
    EXPECT_EQ(parse_arguments(command, {"m", "--width", "8"}).integer("width"), 8);
    EXPECT_THROW(absent.integer("width", 1024), std::logic_error);  // written twice
    EXPECT_THROW(absent.integer("height"), std::logic_error);       // written nowhere
    EXPECT_EQ(absent.integer("height", 3), 3);
    EXPECT_THROW(absent.text("name", "other"), std::logic_error);
    command.options[1].default_value = "0";  // outside [1, 16384]
    EXPECT_THROW(parse_arguments(command, {"m"}), std::logic_error);
}
