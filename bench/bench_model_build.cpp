// One model evaluation's case built from a fit's free values (issue 27): through the template (a copy of the TOML
// tree, set_number and the whole case reader, as fitcase::model_builder did) against io::FreeNumberCase (built once;
// the material, indenter or layer the keys touch rebuilt from typed values). The solve that follows each build in a
// fit is not counted.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "mdr/io/case_template.hpp"
#include "mdr/io/free_number_case.hpp"

namespace {

const std::string load = R"(
[load]
control = "displacement"
history = [[0.0, 0.0], [1.0, 1.0e-6], [30.0, 1.0e-6]]
)";

struct BuildCase {
    std::string text;
    std::vector<std::string> keys;
    std::vector<double> values;
};

const BuildCase& build_case(int which) {
    static const std::vector<BuildCase> cases{
        {R"(
[material]
model = "standard"
G_inf = 1000
G1 = 2000
tau1 = 0.5
[indenter]
shape = "cone"
half_angle_deg = 35
)" + load,
         {"material.G_inf", "material.G1", "material.tau1"},
         {1100.0, 2100.0, 0.6}},
        {R"(
[material]
model = "power_law"
G0 = 1000
t0 = 1
beta = 0.2
[indenter]
shape = "sphere"
R = 5e-6
)" + load,
         {"material.G0", "material.beta"},
         {1100.0, 0.25}},
        {R"(
[material]
model = "standard"
G_inf = 1000
G1 = 2000
tau1 = 0.5
[indenter]
shape = "sphere"
R = 5e-6
[layer]
thickness = 2e-6
interface = "bonded"
)" + load,
         {"layer.thickness"},
         {2.5e-6}},
    };
    return cases.at(static_cast<std::size_t>(which));
}

const char* const case_names[] = {"standard solid, 3 keys", "power law (a series), 2 keys", "layer.thickness"};

void BM_ModelBuildTemplate(benchmark::State& state) {
    const BuildCase& model = build_case(static_cast<int>(state.range(0)));
    const mdr::io::CaseTemplate parsed(model.text, "case");
    for (auto _ : state) {
        mdr::io::CaseTemplate copy = parsed;
        for (std::size_t j = 0; j < model.keys.size(); ++j) copy.set_number(model.keys[j], model.values[j]);
        benchmark::DoNotOptimize(copy.build());
    }
    state.SetLabel(case_names[state.range(0)]);
}
BENCHMARK(BM_ModelBuildTemplate)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

void BM_ModelBuildTyped(benchmark::State& state) {
    const BuildCase& model = build_case(static_cast<int>(state.range(0)));
    const mdr::io::FreeNumberCase free(mdr::io::CaseTemplate(model.text, "case"), model.keys);
    for (auto _ : state) benchmark::DoNotOptimize(free.build(model.values));
    state.SetLabel(case_names[state.range(0)]);
}
BENCHMARK(BM_ModelBuildTyped)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

}  // namespace
