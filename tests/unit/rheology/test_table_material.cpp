// Materials from tables (issue 12): a table sampled from a known Prony series is recovered (G(t) to 1e-6 between
// the samples too), from G(t), J(t) or G'(omega), G''(omega); a noisy table gives a series whose stated residual is
// the true largest residual at the data; tables no series can follow are refused with the reason.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "mdr/error.hpp"
#include "mdr/rheology/table_material.hpp"

namespace mdr::rheology {
namespace {

const Rheology& truth() {
    static const Rheology material = Rheology::prony(1.0e5, {{3.0e5, 2.3e-3}, {1.0e6, 0.047}, {4.0e5, 1.9}});
    return material;
}

std::vector<double> log_space(double lower, double upper, std::size_t count) {
    std::vector<double> values(count);
    for (std::size_t i = 0; i < count; ++i) values[i] = lower * std::pow(upper / lower, static_cast<double>(i) / static_cast<double>(count - 1));
    return values;
}

double worst_relaxation_error(const Rheology& fitted, double lower, double upper) {
    double worst = 0.0;
    for (double t : log_space(lower, upper, 2001)) {
        worst = std::max(worst, std::abs(fitted.relaxation(t) / truth().relaxation(t) - 1.0));
    }
    return worst;
}

TEST(TableMaterial, RecoversAPronySeriesFromEachKindOfTable) {
    MaterialTable relaxation{TableQuantity::relaxation, log_space(1e-4, 1e2, 41), {}, {}};
    MaterialTable creep{TableQuantity::creep, relaxation.abscissa, {}, {}};
    for (double t : relaxation.abscissa) {
        relaxation.values.push_back(truth().relaxation(t));
        creep.values.push_back(truth().creep(t));
    }
    MaterialTable dynamic{TableQuantity::dynamic, log_space(1e-2, 1e4, 41), {}, {}};
    for (double omega : dynamic.abscissa) {
        dynamic.values.push_back(truth().complex_modulus(omega).real());
        dynamic.loss.push_back(truth().complex_modulus(omega).imag());
    }
    for (const MaterialTable* table : {&relaxation, &creep, &dynamic}) {
        const Approximation fit = fit_table(*table);
        EXPECT_LT(worst_relaxation_error(fit.series, 1e-4, 1e2), 1e-6) << static_cast<int>(table->quantity);
        EXPECT_LT(fit.certificate.error, 1e-6);
        EXPECT_EQ(fit.certificate.kind, "fit residual");
    }
    EXPECT_DOUBLE_EQ(fit_table(dynamic).certificate.window.shortest, 1e-4);  // 1 / omega_max
}

TEST(TableMaterial, NoisyTableStatesItsResidual) {
    std::mt19937 random(3);
    std::normal_distribution<double> noise(0.0, 0.01);
    MaterialTable table{TableQuantity::relaxation, log_space(1e-4, 1e2, 61), {}, {}};
    for (double t : table.abscissa) table.values.push_back(truth().relaxation(t) * (1.0 + noise(random)));
    const Approximation fit = fit_table(table);
    double worst = 0.0;
    for (std::size_t i = 0; i < table.abscissa.size(); ++i) {
        worst = std::max(worst, std::abs(fit.series.relaxation(table.abscissa[i]) / table.values[i] - 1.0));
    }
    EXPECT_DOUBLE_EQ(fit.certificate.error, worst);
    EXPECT_LT(worst, 0.04);                                         // about the noise (1% rms, 61 points)
    EXPECT_LT(worst_relaxation_error(fit.series, 1e-4, 1e2), 0.02);  // and the truth within the noise
}

std::string refusal(const MaterialTable& table) {
    try {
        fit_table(table);
    } catch (const InvalidInput& error) {
        return error.key() + ": " + error.rule();
    }
    return "(accepted)";
}

TEST(TableMaterial, RefusesTablesNoSeriesCanFollow) {
    EXPECT_EQ(refusal({TableQuantity::relaxation, {1.0, 2.0, 3.0}, {3.0, 2.0, 2.5}, {}}),
              "G[2]: above the earlier 2: a relaxation modulus cannot increase (no Prony series follows it; noise up "
              "to 5% passes)");
    EXPECT_EQ(refusal({TableQuantity::creep, {1.0, 2.0}, {2.0, 1.0}, {}}).substr(0, 4), "J[1]");
    EXPECT_EQ(refusal({TableQuantity::dynamic, {1.0, 2.0}, {1.0, 2.0}, {1.0, -1.0}}).substr(0, 7), "loss[1]");
    EXPECT_EQ(refusal({TableQuantity::relaxation, {1.0}, {1.0}, {}}).substr(0, 1), "t");
    EXPECT_EQ(refusal({TableQuantity::relaxation, {1.0, 1.0}, {1.0, 1.0}, {}}).substr(0, 4), "t[1]");
    EXPECT_EQ(refusal({TableQuantity::relaxation, {1.0, 2.0}, {1.0}, {}}).substr(0, 1), "G");
    EXPECT_EQ(refusal({TableQuantity::relaxation, {1.0, 2.0}, {1.0, 0.0}, {}}).substr(0, 4), "G[1]");
    // Noise within 5% passes.
    EXPECT_EQ(refusal({TableQuantity::relaxation, {1.0, 2.0, 3.0}, {3.0, 2.0, 2.05}, {}}), "(accepted)");
}

TEST(TableMaterial, ReadsACsvByItsHeader) {
    const auto path = std::filesystem::temp_directory_path() / "mdr_table_material_test.csv";
    {
        std::ofstream file(path);
        file << "omega, loss,storage,comment\n1,0.5,2,a\n10, 0.8,3,b\n\n";
    }
    const MaterialTable table = read_material_table(path);
    EXPECT_EQ(table.quantity, TableQuantity::dynamic);
    EXPECT_EQ(table.abscissa, (std::vector<double>{1.0, 10.0}));
    EXPECT_EQ(table.values, (std::vector<double>{2.0, 3.0}));
    EXPECT_EQ(table.loss, (std::vector<double>{0.5, 0.8}));
    {
        std::ofstream file(path);
        file << "t,G,J\n1,2,0.5\n";
    }
    EXPECT_THROW(read_material_table(path), InvalidInput);
    {
        std::ofstream file(path);
        file << "t,G\n1,x\n";
    }
    EXPECT_THROW(read_material_table(path), InvalidInput);
    std::filesystem::remove(path);
    EXPECT_THROW(read_material_table(path), InvalidInput);
}

// The table's file goes through mdr's one CSV reader (mdr::CsvFile), as measured curves do: a byte-order mark,
// comment lines and quoted names are read as there (before, the table's own parser took the mark and the comment
// for the header and "t","G" for a row), and a row short of a field is refused with its line and the rule.
TEST(TableMaterial, ReadsItsFileLikeAMeasuredCurve) {
    const auto path = std::filesystem::temp_directory_path() / "mdr_table_material_reader_test.csv";
    {
        std::ofstream file(path, std::ios::binary);
        file << "\xEF\xBB\xBF# a master curve\r\n\"t\", \"G\"\r\n1,2\r\n# a note\r\n10,1.5\r\n";
    }
    const MaterialTable table = read_material_table(path);
    EXPECT_EQ(table.quantity, TableQuantity::relaxation);
    EXPECT_EQ(table.abscissa, (std::vector<double>{1.0, 10.0}));
    EXPECT_EQ(table.values, (std::vector<double>{2.0, 1.5}));
    {
        std::ofstream file(path);
        file << "t,G\n1,2\n10\n";
    }
    try {
        read_material_table(path);
        ADD_FAILURE() << "a row short of a field was read";
    } catch (const InvalidInput& error) {
        EXPECT_EQ(error.key(), "file");
        EXPECT_NE(std::string(error.what()).find("line 3 has 1 fields; the header has 2"), std::string::npos)
            << error.what();
    }
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace mdr::rheology
