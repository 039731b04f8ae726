// Tables boxlod reads back (base/csv.h read_csv_table: a sweep's results and
// timings), under a header with a column of every kind.
#include "base/csv.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using boxlod::CsvValue;
    static const std::vector<boxlod::CsvColumn> columns = {{"model", CsvValue::text},
                                                           {"faces", CsvValue::count},
                                                           {"distance", CsvValue::number},
                                                           {"depth_error", CsvValue::optional_number},
                                                           {"psnr", CsvValue::metric}};
    return boxlod::fuzz::expect_only_input_errors(
        [&] { boxlod::read_csv_table(boxlod::fuzz::text(data, size), "fuzz.csv", columns); });
}
