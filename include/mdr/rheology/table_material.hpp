#pragma once
/// \file
/// A material given by measured material functions: relaxation modulus G(t), creep compliance J(t), or storage and
/// loss moduli G'(omega), G''(omega) (a master curve), turned into a Prony series by a non-negative linear least-
/// squares fit on a logarithmic grid of relaxation (or retardation) times, with the fit residual reported.

#include <filesystem>
#include <string>
#include <vector>

#include "mdr/rheology/approximation.hpp"

namespace mdr::rheology {

/// What a table holds.
enum class TableQuantity {
    relaxation,  ///< t [s], G [Pa]
    creep,       ///< t [s], J [1/Pa]
    dynamic,     ///< omega [rad/s], storage [Pa], loss [Pa]
};

/// Measured material functions.
struct MaterialTable {
    TableQuantity quantity = TableQuantity::relaxation;
    std::vector<double> abscissa{};  ///< t or omega, ascending, > 0
    std::vector<double> values{};    ///< G, J or storage
    std::vector<double> loss{};      ///< loss modulus (dynamic only)

    /// The keys as a case names them: t / omega, then G / J / storage, then loss.
    const char* abscissa_key() const;
    const char* values_key() const;

    /// Refuses a table that no Prony series can represent, naming the key and the reason: fewer than 2 points,
    /// lengths that differ, abscissae not ascending or not > 0, values not finite or not > 0 (a loss modulus < 0),
    /// a relaxation modulus that increases or a creep compliance or storage modulus that decreases by more than
    /// noise_allowance (relative, against the extreme so far).
    void validate() const;
};

/// Relative change against the trend that validate() lets pass as measurement noise.
inline constexpr double noise_allowance = 0.05;

/// Reads a CSV with a header naming its columns: `t,G`, `t,J` or `omega,storage,loss` (other columns are
/// ignored; a file with both G and J is ambiguous and refused), read by mdr's one CSV reader (mdr::CsvFile: comments,
/// quotes, a field count per row equal to the header's). Throws mdr::InvalidInput with key `file`.
MaterialTable read_material_table(const std::filesystem::path& path);

/// The Prony series (for creep data: the creep function J_g + t/eta_f + sum J_j (1 - exp(-t/lambda_j)), then
/// Rheology::from_creep) fitted by non-negative least squares to the table's values relative to themselves (each
/// point weighs by 1/value), on log grids of 4, 8 and 16 times per decade spanning the data's times (1/omega for
/// dynamic data) a factor 3 beyond each end, plus the constant (G_inf, J_g) and, for creep, the flow term; the
/// grid with the smallest largest residual is kept and its zero terms dropped. The certificate's error is the
/// largest relative residual at the data points (kind "fit residual"), its window the data's range of times.
/// Throws mdr::InvalidInput (validate()).
Approximation fit_table(const MaterialTable& table);

}  // namespace mdr::rheology
