#pragma once
// Reading chosen columns of a measured curve's CSV file, with an optional selection of rows by segment.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace mdr::fit {

/// A numeric column to read: its name in the file's header and the `[[fit.data]]` key that named it (for messages).
struct CsvColumn {
    std::string name;
    std::string key;
};

/// The kept rows of the requested columns.
struct CsvColumns {
    std::vector<std::vector<double>> values;  ///< one vector per requested column, in the order requested
    std::vector<std::size_t> lines;           ///< the file's line number (from 1) of each kept row
};

/// Reads `columns` from `file`: a header line of comma-separated names, then one row per line. Empty lines and
/// lines starting with `#` are skipped; fields are trimmed of blanks and of enclosing double quotes; line ends
/// may be `\n` or `\r\n`. With a `segment_column`, only rows whose field there equals one of `segments` are kept
/// (every row when `segments` is empty), and each of `segments` must select at least one row. Every kept value of
/// a requested column must be a finite number; other columns and rows are not looked at. Throws mdr::InvalidInput
/// (keys `file`, the column's key, `segment_column`, `segments`).
CsvColumns read_csv_columns(const std::filesystem::path& file, const std::vector<CsvColumn>& columns,
                            const std::string& segment_column, const std::vector<std::string>& segments);

}  // namespace mdr::fit
