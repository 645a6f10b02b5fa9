// read_fit_data: one `[[fit.data]]` table to its CurveSource (paths relative to the case, units by number or name,
// segments as strings or integers), and its refusals.

#include "fitcase/fit_data_reader.hpp"

#include <gtest/gtest.h>

#include "mdr/error.hpp"
#include "mdr/io/units.hpp"

namespace mdr::fitcase {
namespace {

CurveSource read(const std::string& text, const std::filesystem::path& directory = "/cases",
                      const std::string& units = "SI") {
    const toml::table table = toml::parse(text);
    io::TableReader reader(table, "fit.data[0]");
    return read_fit_data(reader, directory, io::unit_system(units));
}

std::string message(const std::string& text) {
    try {
        read(text);
    } catch (const InvalidInput& error) {
        return error.what();
    }
    return "(accepted)";
}

TEST(FitDataReader, MapsEveryKey) {
    const CurveSource source = read(R"(
        file = "data/curve.csv"
        name = "cell 1"
        time = "t"
        piezo = "z"
        deflection = "defl"
        spring_constant = 0.019
        units = { time = "ms", length = "nm", force = 1e-6 }
        segment_column = "segment"
        segments = ["extend", 2]
    )");
    EXPECT_EQ(source.file, std::filesystem::path("/cases/data/curve.csv"));
    EXPECT_EQ(source.name, "cell 1");
    EXPECT_EQ(source.time_column, "t");
    EXPECT_EQ(source.depth_column, "");
    EXPECT_EQ(source.force_column, "");
    EXPECT_EQ(source.piezo_column, "z");
    EXPECT_EQ(source.deflection_column, "defl");
    EXPECT_EQ(source.spring_constant, 0.019);
    EXPECT_EQ(source.time_unit, 1e-3);
    EXPECT_EQ(source.length_unit, 1e-9);
    EXPECT_EQ(source.force_unit, 1e-6);
    EXPECT_EQ(source.segment_column, "segment");
    EXPECT_EQ(source.segments, (std::vector<std::string>{"extend", "2"}));
}

TEST(FitDataReader, DefaultsAndAbsolutePaths) {
    const CurveSource source = read(R"(
        file = "/data/curve.csv"
        time = "t_s"
        depth = "indentation_m"
        force = "force_N"
    )");
    EXPECT_EQ(source.file, std::filesystem::path("/data/curve.csv"));
    EXPECT_EQ(source.name, "");
    EXPECT_EQ(source.depth_column, "indentation_m");
    EXPECT_EQ(source.force_column, "force_N");
    EXPECT_FALSE(source.spring_constant.has_value());
    EXPECT_EQ(source.time_unit, 1.0);
    EXPECT_EQ(source.length_unit, 1.0);
    EXPECT_EQ(source.force_unit, 1.0);
    EXPECT_TRUE(source.segments.empty());
}

TEST(FitDataReader, UnitNamesAreSiPrefixesOfTheBase) {
    const auto length = [](const std::string& unit) {
        return read("file = \"c.csv\"\ntime = \"t\"\nunits = { length = " + unit + " }\n").length_unit;
    };
    EXPECT_EQ(length("\"m\""), 1.0);
    EXPECT_EQ(length("\"mm\""), 1e-3);
    EXPECT_EQ(length("\"um\""), 1e-6);
    EXPECT_EQ(length("\"µm\""), 1e-6);
    EXPECT_EQ(length("\"nm\""), 1e-9);
    EXPECT_EQ(length("\"pm\""), 1e-12);
    EXPECT_EQ(length("1e-9"), 1e-9);
    EXPECT_EQ(read("file = \"c.csv\"\ntime = \"t\"\nunits = { time = \"s\", force = \"pN\" }\n").force_unit, 1e-12);
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\nunits = { length = \"nN\" }\n"),
              "fit.data[0].units.length = \"nN\": must be a number > 0 (the unit in m) or m with an SI prefix: p, n, "
              "u or µ, m, c, k (e.g. \"nm\")");
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\nunits = { time = 0 }\n"),
              "fit.data[0].units.time = 0: must be > 0");
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\nunits = { lenght = \"nm\" }\n"),
              "fit.data[0].units.lenght = 'nm': unknown key; did you mean 'length'?");
}

TEST(FitDataReader, UnitsConvertToTheCasesSystem) {
    // The factor takes a data unit to the case's unit (the units table's sizes), not to SI: in um-nN-s a column in
    // nm is 1e-3 um, in m 1e6 um; a number is the data unit's size in SI; absent, the data are in the case's units.
    const auto in_cells = [](const std::string& units) {
        return read("file = \"c.csv\"\ntime = \"t\"\nspring_constant = 0.02\nunits = " + units + "\n", "/cases",
                    "um-nN-s");
    };
    const CurveSource named =
        in_cells("{ time = \"ms\", length = \"nm\", force = \"pN\", spring_constant = \"N/m\" }");
    EXPECT_DOUBLE_EQ(named.time_unit, 1e-3);
    EXPECT_DOUBLE_EQ(named.length_unit, 1e-3);
    EXPECT_DOUBLE_EQ(named.force_unit, 1e-3);
    EXPECT_DOUBLE_EQ(named.spring_constant_unit, 1e3);  // 1 N/m = 1e3 nN/um
    EXPECT_EQ(named.spring_constant, 0.02);             // as given, for messages
    EXPECT_DOUBLE_EQ(in_cells("{ spring_constant = \"nN/um\" }").spring_constant_unit, 1.0);
    EXPECT_DOUBLE_EQ(in_cells("{ spring_constant = \"pN/nm\" }").spring_constant_unit, 1.0);  // 1e-12 / 1e-9 N/m
    EXPECT_DOUBLE_EQ(in_cells("{ spring_constant = \"mN/m\" }").spring_constant_unit, 1.0);   // 1 mN/m = 1 nN/um
    const CurveSource si = in_cells("{ length = \"m\", force = 1.0, spring_constant = \"N/m\" }");
    EXPECT_DOUBLE_EQ(si.length_unit, 1e6);
    EXPECT_DOUBLE_EQ(si.force_unit, 1e9);
    EXPECT_EQ(in_cells("{ spring_constant = \"N/m\" }").length_unit, 1.0);
    const std::string in_um = "file = \"c.csv\"\ntime = \"t\"\nunits = { length = \"um\" }\n";
    EXPECT_EQ(read(in_um, "/cases", "mm-N-s").length_unit, 1e-3);

    const toml::table table = toml::parse(
        "file = \"d.csv\"\nvelocity = \"v\"\nrestitution = \"e\"\nunits = { velocity = \"mm/s\", time = \"ms\" }\n");
    io::TableReader reader(table, "fit.data[1]");
    const fit::ReboundSource drops = read_rebound_data(reader, "/cases", io::unit_system("nm-nN-s"));
    EXPECT_DOUBLE_EQ(drops.velocity_unit, 1e6);  // 1 mm/s = 1e6 nm/s
    EXPECT_DOUBLE_EQ(drops.time_unit, 1e-3);
}

TEST(FitDataReader, ASpringConstantStatesItsUnitWhereTheCasesIsNotNewtonPerMetre) {
    // 0.019 reads as N/m to an AFM user and as nN/um to a um-nN-s case: refused bare there and in mm-N-s (N/mm),
    // accepted bare where the case's force / length is N/m: SI, and nm-nN-s (nN/nm = N/m).
    const std::string bare = "file = \"c.csv\"\ntime = \"t\"\nspring_constant = 0.019\n";
    EXPECT_DOUBLE_EQ(read(bare, "/cases", "SI").spring_constant_unit, 1.0);
    EXPECT_DOUBLE_EQ(read(bare, "/cases", "nm-nN-s").spring_constant_unit, 1.0);
    for (const std::string system : {"um-nN-s", "mm-N-s"}) {
        try {
            read(bare, "/cases", system);
            ADD_FAILURE() << system << ": a bare spring constant was taken";
        } catch (const InvalidInput& error) {
            EXPECT_EQ(std::string(error.what()).rfind("fit.data[0].spring_constant = 0.019: a spring constant in a " +
                                                          system + " case must state its unit: "
                                                                   "fit.data[0].units.spring_constant = \"N/m\"",
                                                      0),
                      0U)
                << error.what();
        }
    }
    try {
        read(bare + "units = { spring_constant = \"N/cm2\" }\n", "/cases", "um-nN-s");
        ADD_FAILURE() << "N/cm2 was taken";
    } catch (const InvalidInput& error) {
        EXPECT_NE(std::string(error.what()).find("fit.data[0].units.spring_constant = \"N/cm2\": must be a force"),
                  std::string::npos)
            << error.what();
    }
}

TEST(FitDataReader, RefusesUnknownKeysAndWrongTypes) {
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\ndepht = 'd'\n"),
              "fit.data[0].depht = 'd': unknown key; did you mean 'depth'?");
    EXPECT_EQ(message("time = \"t\"\n"), "fit.data[0].file = (missing): is required");
    EXPECT_EQ(message("file = \"c.csv\"\ntime = 3\n"), "fit.data[0].time = 3: must be a string");
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\nspring_constant = \"stiff\"\n"),
              "fit.data[0].spring_constant = 'stiff': must be a number");
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\nsegments = \"extend\"\n"),
              "fit.data[0].segments = 'extend': must be an array of strings or integers");
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\nsegments = [\"extend\", 1.5]\n"),
              "fit.data[0].segments[1] = 1.5: must be an array of strings or integers");
    EXPECT_EQ(message("file = \"c.csv\"\ntime = \"t\"\nunits = \"nm\"\n"),
              "fit.data[0].units = 'nm': must be a table");
}

}  // namespace
}  // namespace mdr::fitcase
