#pragma once
/// \file
/// The columns of a run's history, declared once: history.csv (mdr/io/result_files.hpp) and `mdr.run`'s history
/// arrays are both written from this list (spec: docs/case-format.md, "Result directory").

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "mdr/drivers/indentation.hpp"

namespace mdr::io {

/// One column of the history: its header name, whether a result has it, and its value at a written step.
struct HistoryColumn {
    std::string_view name;                                          ///< the history.csv header, e.g. "deflection"
    bool (*present)(const drivers::IndentationResult& result);      ///< whether `result` has this column
    double (*value)(const drivers::IndentationResult& result, std::size_t row);  ///< its value in row `row`
};

/// Every history column in file order: t,d,F,a, then each control's columns (v; z,deflection; shore; u,Fx,c;
/// v_t,omega).
std::span<const HistoryColumn> history_schema();

/// The columns `result` has, in file order; each has result.time.size() rows.
std::vector<HistoryColumn> history_columns(const drivers::IndentationResult& result);

}  // namespace mdr::io
