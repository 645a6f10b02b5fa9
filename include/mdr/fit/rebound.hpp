#pragma once
/// \file
/// Measured rebounds for fitting: the coefficient of restitution e (and optionally the contact time T) of impacts
/// at several approach speeds v0, each an impact of the case's indenter on its material (drivers::run_case,
/// eq. 37-39). Where they come from (a CSV file and its columns, or arrays) and what the fit receives.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace mdr::fit {

/// The columns of rebound data in a CSV file (`[[fit.data]]` with `kind = "rebound"`). The uncertainty of e (and
/// of T) is a number for every row, a column, or left out (estimated from the data, see ReboundData).
struct ReboundSource {
    std::filesystem::path file;                 ///< CSV file with a header row of column names
    std::string name;                           ///< the data set's name ("" gives the file's stem)
    std::string velocity_column;                ///< approach speed v0 > 0
    std::string restitution_column;             ///< coefficient of restitution e in [0, 1]
    std::string contact_time_column;            ///< contact time T > 0 ("" when not measured)
    std::optional<double> restitution_error{};  ///< standard deviation of every e
    std::string restitution_error_column;       ///< or a column of them ("" when not given)
    std::optional<double> contact_time_error{}; ///< standard deviation of every T (in the time unit)
    std::string contact_time_error_column;      ///< or a column of them ("" when not given)
    std::optional<double> mass{};               ///< impactor mass (case's units); unset: the case's `indenter.mass`
    double velocity_unit = 1.0;                 ///< the case's velocity units per unit of the velocity column
    double time_unit = 1.0;                     ///< the case's time units per unit of the contact time columns
};

/// Measured rebounds in the case's units (SI names below for a case in SI), validated: one impact of mass `mass` at
/// each approach speed.
struct ReboundData {
    std::string name;                         ///< for messages and outputs (the file stem, or given)
    double mass = 0.0;                        ///< impactor mass m [kg] > 0
    std::vector<double> velocity;             ///< approach speeds v0 [m/s] > 0
    std::vector<double> restitution;          ///< e = rebound speed / v0, in [0, 1]
    std::vector<double> restitution_error;    ///< standard deviation of each e (> 0)
    std::vector<double> contact_time;         ///< T [s] > 0 per impact, or empty (not measured)
    std::vector<double> contact_time_error;   ///< standard deviation of each T [s] (> 0), empty without T
};

/// The fewest impacts a rebound data set may have.
inline constexpr std::size_t minimum_rebound_rows = 1;

/// Measured rebounds before their checks: errors as given (empty: estimate; one value: every row; else per row).
struct ReboundArrays {
    std::string name;                        ///< see ReboundData
    std::optional<double> mass{};            ///< see ReboundData (required)
    std::vector<double> velocity{};          ///< see ReboundData
    std::vector<double> restitution{};       ///< see ReboundData
    std::vector<double> contact_time{};      ///< see ReboundData
    std::vector<double> restitution_error{}; ///< empty, one value, or one per row
    std::vector<double> contact_time_error{};///< empty, one value, or one per row
};

/// Validates rebound arrays in the case's units and fills their uncertainties. Throws mdr::InvalidInput (keys `mass`,
/// `velocity`, `restitution`, `contact_time`, `restitution_error`, `contact_time_error`; a caller prefixes them)
/// for: a mass that is missing or not > 0, no rows, arrays of different lengths, a value that is not finite, a
/// speed or contact time not > 0, e outside [0, 1], an uncertainty not > 0, and an uncertainty to be estimated
/// from fewer than 3 rows. An uncertainty left out is estimated by estimate_scatter.
ReboundData make_rebound(ReboundArrays arrays);

/// Reads rebound data from its CSV source (columns by name, units) and validates it as make_rebound does; the
/// file, column and line name each error. `case_mass` (the case's `indenter.mass`) stands for a source without
/// its own mass. Keys as for make_rebound plus `file` and the column keys.
ReboundData load_rebound(const ReboundSource& source, std::optional<double> case_mass);

/// The noise of measured values y_i at abscissae x_i (any order, at least 3 distinct): each interior point (in the
/// order of x) is compared with the straight line through its two neighbours, r_i = y_i - (w_l y_l + w_r y_r) with
/// the interpolation weights w_l + w_r = 1; for independent noise of deviation s, r_i has the deviation
/// s sqrt(1 + w_l^2 + w_r^2), so s = 1.4826 MAD(r_i / sqrt(1 + w_l^2 + w_r^2)) (MAD about 0). A curved e(v0)
/// adds its curvature: an upper bound for sparse or strongly bent data. 0 for fewer than 3 points.
double estimate_scatter(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace mdr::fit
