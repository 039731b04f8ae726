#include "base/csv.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace boxlod;

TEST(Csv, PlainFieldsAreJoinedAsTheyAre) {
    EXPECT_EQ(csv_row({"manual", "top-down", "0.5", ""}), "manual,top-down,0.5,");
}

TEST(Csv, FieldsWithCommasQuotesOrLineBreaksAreQuotedAsRfc4180Says) {
    EXPECT_EQ(csv_row({"distance:40,80", "say \"hi\"", "two\nlines"}),
              "\"distance:40,80\",\"say \"\"hi\"\"\",\"two\nlines\"");
}

TEST(Csv, FieldsReadBackWhatRowWrote) {
    const std::vector<std::string> fields = {"a,b", "", "\"quoted\"", "plain", ",", "\"\""};
    EXPECT_EQ(csv_fields(csv_row(fields)), fields);
    EXPECT_EQ(csv_fields(""), std::vector<std::string>{""});
    EXPECT_EQ(csv_fields("x,,y"), (std::vector<std::string>{"x", "", "y"}));
}

namespace {

const std::vector<CsvColumn> table_columns = {{"model", CsvValue::text},
                                              {"faces", CsvValue::count},
                                              {"distance", CsvValue::number},
                                              {"error", CsvValue::optional_number},
                                              {"psnr", CsvValue::metric, {0, INFINITY}}};

// The InputError read_csv_table throws for `rows` under the right header, or "".
std::string refusal(const std::string& rows) {
    return test::input_error_of(
        [&] { read_csv_table("model,faces,distance,error,psnr\n" + rows, "results.csv", table_columns); });
}

}  // namespace

TEST(Csv, ATableReadBackKeepsItsRowsAndLineNumbers) {
    const auto records =
        read_csv_table("model,faces,distance,error,psnr\nhouse,12,1.5,,inf\n\n\"a,b\",0,0,0.25,0.5\n",
                       "results.csv", table_columns);
    ASSERT_EQ(records.size(), 2u);
    EXPECT_EQ(records[0].line, 2);
    EXPECT_EQ(records[0].fields, (std::vector<std::string>{"house", "12", "1.5", "", "inf"}));
    EXPECT_EQ(records[1].line, 4);
    EXPECT_EQ(records[1].fields[0], "a,b");
    EXPECT_TRUE(read_csv_table("", "results.csv", table_columns).empty());
}

// What a resumed sweep or --merge met in hand-edited or damaged tables (issue 47.4):
// each refused with file, line and column.
TEST(Csv, ATableReadBackRefusesWhatItsColumnsCannotHold) {
    EXPECT_EQ(refusal("house,12,1.5,,inf\n"), "");
    EXPECT_EQ(refusal("house,twelve,1.5,,1\n"),
              "results.csv: line 2: faces: 'twelve' is not a count (a whole number >= 0)");
    EXPECT_EQ(refusal("house,-1,1.5,,1\n"),
              "results.csv: line 2: faces: '-1' is not a count (a whole number >= 0)");
    EXPECT_EQ(refusal("house,99999999999999999999,1.5,,1\n"),
              "results.csv: line 2: faces: '99999999999999999999' is not a count (a whole number >= 0)");
    EXPECT_EQ(refusal("house,12,nan,,1\n"),
              "results.csv: line 2: distance: 'nan' is not a finite number >= 0");
    EXPECT_EQ(refusal("house,12,1, 2,1\n"), "results.csv: line 2: error: ' 2' is not a finite number >= 0");
    EXPECT_EQ(refusal("house,12,1,,nan\n"),
              "results.csv: line 2: psnr: 'nan' is not a metric value in [0, inf]");
    EXPECT_EQ(refusal("house,12,1,,\n"), "results.csv: line 2: psnr: '' is not a metric value in [0, inf]");
    // A hand-edited value outside what its metric takes (issue 70's hostile-input run: -5, 1e300 were copied
    // on).
    EXPECT_EQ(refusal("house,12,1,,-5\n"),
              "results.csv: line 2: psnr: '-5' is not a metric value in [0, inf]");
    EXPECT_EQ(refusal("house,12,1.5,,1\nhouse,12\n"), "results.csv: line 3: 2 fields, not 5");  // a cut row
    EXPECT_EQ(refusal(std::string(5000, 'x') + ",1,1,,1\n"),
              "results.csv: line 2: model: a field of 5000 bytes (at most 4096)");
    EXPECT_NE(refusal(std::string(1000000, 'x') + "\n").find("results.csv: line 2: a line of 1000000 bytes"),
              std::string::npos);
    EXPECT_EQ(refusal(std::string("ho\0use,12,1.5,,1\n", 17)),
              "results.csv: line 2: model: a control character (byte 0)");
    EXPECT_EQ(refusal("hou\tse,12,1.5,,1\n"), "results.csv: line 2: model: a control character (byte 9)");
    EXPECT_EQ(refusal("ho\xffuse,12,1.5,,1\n"), "results.csv: line 2: model: bytes that are not UTF-8");
    EXPECT_EQ(refusal("ho\xc3use,12,1.5,,1\n"), "results.csv: line 2: model: bytes that are not UTF-8");
    EXPECT_EQ(refusal("Stra\xc3\x9f"
                      "e,12,1.5,,1\n"),
              "");  // UTF-8 is text
    EXPECT_EQ(refusal("\xe0\x80\xaf,12,1.5,,1\n"),
              "results.csv: line 2: model: bytes that are not UTF-8");  // overlong '/'
    EXPECT_EQ(refusal("\xf4\x90\x80\x80,12,1.5,,1\n"),
              "results.csv: line 2: model: bytes that are not UTF-8");  // past U+10FFFF
    EXPECT_EQ(refusal("a\xc2\x85,12,1.5,,1\n"),
              "results.csv: line 2: model: a control character (U+0080 to U+009F)");
    EXPECT_EQ(
        test::input_error_of(
            [] { read_csv_table("some,other,columns\n1,2,3\n", "results.csv", table_columns); }),
        "results.csv: its columns are not model,faces,distance,error,psnr (a table of another run or kind)");
}
