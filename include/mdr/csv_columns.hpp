#pragma once
/// \file
/// The one CSV reader of mdr: chosen numeric columns of a file with a header line, read line by line (the file is
/// never held whole), with an optional selection of rows by segment. Measured curves (`[[fit.data]]`), rebound
/// data and material tables (`model = "table"`, `file`) read through it.

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace mdr {

/// A numeric column to read: its name in the file's header and the key that named it (for messages).
struct CsvColumn {
    std::string name;
    std::string key;
};

/// The kept rows of the requested columns.
struct CsvColumns {
    std::vector<std::vector<double>> values;  ///< one vector per requested column, in the order requested
    std::vector<std::size_t> lines;           ///< the file's line number (from 1) of each kept row
};

/// A CSV file opened at its header: a header line of comma-separated names, then one row per line. Empty lines and
/// lines starting with `#` are skipped; fields are trimmed of blanks and of enclosing double quotes; line ends may
/// be `\n` or `\r\n`; a UTF-8 byte-order mark is ignored. Throws mdr::InvalidInput (key `file`) for a file that is
/// missing, not a regular file, unreadable or without a header line.
class CsvFile {
public:
    /// Opens `file` and reads its header line.
    explicit CsvFile(const std::filesystem::path& file);

    /// The header's column names, trimmed.
    const std::vector<std::string>& header() const { return header_; }

    /// Reads `columns` from the rows after the header (once per file). With a `segment_column`, only rows whose
    /// field there equals one of `segments` are kept (every row when `segments` is empty), and each of `segments`
    /// must select at least one row. Every row must have as many fields as the header; every kept value of a
    /// requested column must be a finite number; other columns are not looked at. Throws mdr::InvalidInput (keys
    /// `file`, the column's key, `segment_column`, `segments`).
    CsvColumns read(const std::vector<CsvColumn>& columns, const std::string& segment_column,
                    const std::vector<std::string>& segments);

private:
    /// The next line that is neither empty nor a comment, and its number; false at the end of the file.
    bool next_line();

    std::filesystem::path file_;
    std::ifstream in_;
    std::string line_;             ///< the current line, reused from line to line
    std::size_t line_number_ = 0;  ///< of line_, from 1
    std::vector<std::string> header_;
};

/// CsvFile(file).read(columns, segment_column, segments).
CsvColumns read_csv_columns(const std::filesystem::path& file, const std::vector<CsvColumn>& columns,
                            const std::string& segment_column, const std::vector<std::string>& segments);

}  // namespace mdr
