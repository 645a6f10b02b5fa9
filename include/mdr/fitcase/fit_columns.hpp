#pragma once
/// \file
/// The columns of a fit's tables, declared once: curves.csv, functions.csv and dynamic.csv (mdr/fitcase/fit_files.hpp)
/// and mdr.fit's `curves` and `material` arrays (python/bindings/bind_fit.cpp) are all written from these lists
/// (docs/case-format.md, "Fitting").

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "mdr/fit/fit.hpp"

namespace mdr::fitcase {

/// One column of curves.csv after `curve` (the curve's name): its header and its value at a point of a curve.
struct CurveColumn {
    std::string_view name;                                         ///< the curves.csv header, e.g. "residual"
    double (*value)(const fit::CurveFit& curve, std::size_t point);  ///< its value at `point`
};

/// curves.csv's columns after `curve`, in file order: t (nan where the file records no time; for rebound data the
/// speed v0), measured, model, residual (model - measured), drive (fit::CurveFit::drive, nan where there is none).
std::span<const CurveColumn> curve_columns();

/// One column of a table of the fitted material: its header and its values.
struct MaterialColumn {
    std::string name;                   ///< e.g. "G_lower"
    const std::vector<double>* values;  ///< one value per row
};

/// A table of the fitted material (fit::MaterialBands): its file name and its columns in file order.
struct MaterialTable {
    std::string file;                     ///< "functions.csv" or "dynamic.csv"
    std::vector<MaterialColumn> columns;  ///< the abscissa first, then each function with its 95 % band
};

/// functions.csv (t,G,G_lower,G_upper,J,J_lower,J_upper) and dynamic.csv (omega,storage,storage_lower,
/// storage_upper,loss,loss_lower,loss_upper) of `material`, whose columns point into it.
std::vector<MaterialTable> material_tables(const fit::MaterialBands& material);

}  // namespace mdr::fitcase
