#include "base/csv.h"

#include <gtest/gtest.h>

using namespace boxlod;

TEST(Csv, PlainFieldsAreJoinedAsTheyAre) {
    EXPECT_EQ(csv_row({"manual", "top-down", "0.5", ""}), "manual,top-down,0.5,");
}

TEST(Csv, FieldsWithCommasQuotesOrLineBreaksAreQuotedAsRfc4180Says) {
    EXPECT_EQ(csv_row({"distance:40,80", "say \"hi\"", "two\nlines"}), "\"distance:40,80\",\"say \"\"hi\"\"\",\"two\nlines\"");
}

TEST(Csv, FieldsReadBackWhatRowWrote) {
    const std::vector<std::string> fields = {"a,b", "", "\"quoted\"", "plain", ",", "\"\""};
    EXPECT_EQ(csv_fields(csv_row(fields)), fields);
    EXPECT_EQ(csv_fields(""), std::vector<std::string>{""});
    EXPECT_EQ(csv_fields("x,,y"), (std::vector<std::string>{"x", "", "y"}));
}
