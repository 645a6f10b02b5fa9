#pragma once
/// \file
/// Where a measured curve of a fit case comes from (`[[fit.data]]`: a CSV file and its columns, or an AFM instrument
/// file) and its reading into a fit::Curve in the case's units. The case reader fills the source
/// (fitcase::read_fit_data converts the file's units to the case's); load_curve reads it.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "mdr/fit/curve.hpp"

namespace mdr::fitcase {

/// A curve's columns in a CSV file (`[[fit.data]]` of a fit case). Either `depth_column` (indentation, positive
/// into the body) or the raw AFM pair `piezo_column` + `deflection_column` with `spring_constant` gives the depth;
/// `force_column` or the deflection times the spring constant gives the force.
struct CurveSource {
    std::filesystem::path file;             ///< CSV file with a header row of column names, or an instrument file
    /// The file is an AFM instrument file (mdr/instrument/read_curves.hpp: no column is named): time, height,
    /// deflection, spring constant and segment names come from the file, in SI, converted to the case's units by
    /// time_unit, length_unit and force_unit (the case's unit per second, metre and newton).
    bool instrument = false;
    std::optional<std::size_t> curve{};     ///< instrument file: which curve of a map (`curve = N`)
    std::string name;                       ///< the curve's name ("" gives the file's stem)
    std::string time_column;                ///< time
    std::string depth_column;               ///< indentation, positive into the body ("" when raw AFM columns are used)
    std::string force_column;               ///< force on the indenter, positive in compression ("" for raw AFM)
    std::string piezo_column;               ///< AFM: height of the cantilever base, larger = farther from the sample
    std::string deflection_column;          ///< AFM: cantilever deflection, positive = bent away from the sample
    /// AFM: cantilever spring constant, in units of spring_constant_unit (an instrument file: N/m, for a file that
    /// records none)
    std::optional<double> spring_constant;
    /// Instrument file that records the deflection signal uncalibrated: deflection per volt (AFM Workshop) or per
    /// ampere (NT-MDT), m/V or m/A (instrument::ReadOptions::sensitivity)
    std::optional<double> sensitivity;
    double spring_constant_unit = 1.0;      ///< the curve's force / length per unit of spring_constant
    double time_unit = 1.0;                 ///< the curve's time units per unit of the time column
    double length_unit = 1.0;               ///< the curve's length units per unit of the depth, piezo and deflection
    double force_unit = 1.0;                ///< the curve's force units per unit of the force column
    std::string segment_column;             ///< column naming each row's segment ("" keeps every row)
    std::vector<std::string> segments;      ///< segments kept (every segment when empty), e.g. {"extend", "pause"}
    std::optional<fit::Fitted> fitted{};    ///< fit::Curve::fitted
    fit::RowSelection rows{};               ///< the rows kept (fit::select_rows)
    bool preloaded = false;                 ///< fit::Curve::preloaded (`start = "preloaded"`)
};

/// Reads and validates a curve from its CSV source and estimates its noise, contact point and baseline
/// (fit::estimate_contact). Throws mdr::InvalidInput naming the file, column and row for a missing file or column,
/// a value that is not a finite number or (in the case's units) not 0 or of a magnitude from 1e-100 to 1e100 (the
/// unit or spring constant is named when it takes a file's value out of that range), time not strictly increasing,
/// or too few rows; and for a source that
/// names both or neither depth sources (a depth column, or the AFM piezo and deflection columns with a spring
/// constant > 0), a force column beside the AFM columns, or segments that select no row. The keys of its errors
/// are those of a `[[fit.data]]` table (`time`, `force`, `segments`, ...): a caller prefixes them
/// (InvalidInput::with_prefix). Only the used columns of the kept rows are read: other columns may hold anything.
/// An instrument source (CurveSource::instrument) is read by load_instrument_curve
/// (mdr/fitcase/instrument_curve.hpp).
fit::Curve load_curve(const CurveSource& source);

}  // namespace mdr::fitcase
