#include "material_reader.hpp"

#include "mdr/error.hpp"

namespace mdr::io {

const std::vector<std::string>& model_names() {
    static const std::vector<std::string> names{"elastic", "viscous", "kelvin_voigt", "maxwell", "standard", "prony"};
    return names;
}

rheology::Rheology read_rheology(TableReader& table, const std::string& modulus, std::vector<std::string> extra_keys) {
    const std::string model = table.string("model");
    const std::string G = modulus;
    std::vector<std::string> keys;
    if (model == "elastic") keys = {G};
    else if (model == "viscous") keys = {"eta"};
    else if (model == "kelvin_voigt") keys = {G, "eta"};
    else if (model == "maxwell") keys = {G, "tau"};
    else if (model == "standard") keys = {G + "_inf", G + "1", "tau1"};
    else if (model == "prony") keys = {G + "_inf", "terms"};
    else {
        std::string names;
        for (const auto& name : model_names()) names += (names.empty() ? "" : ", ") + name;
        throw InvalidInput(table.key_path("model"), "\"" + model + "\"", "unknown model; one of " + names);
    }
    std::vector<std::string> known = keys;
    known.push_back("model");
    known.insert(known.end(), extra_keys.begin(), extra_keys.end());
    table.reject_unknown(known);
    const std::string prefix = table.key_path("");
    try {
        const auto value = [&](const std::string& key) { return table.number(key); };
        if (model == "elastic") return rheology::Rheology::elastic(value(G));
        if (model == "viscous") return rheology::Rheology::viscous(value("eta"));
        if (model == "kelvin_voigt") return rheology::Rheology::kelvin_voigt(value(G), value("eta"));
        if (model == "maxwell") return rheology::Rheology::maxwell(value(G), value("tau"));
        if (model == "standard") return rheology::Rheology::standard(value(G + "_inf"), value(G + "1"), value("tau1"));
        std::vector<rheology::RelaxationTerm> terms;
        for (const auto& [modulus_k, time_k] : table.pairs("terms", G.c_str(), "tau")) terms.push_back({modulus_k, time_k});
        return rheology::Rheology::prony(value(G + "_inf"), std::move(terms));
    } catch (const InvalidInput& error) {
        if (error.key().rfind(prefix, 0) == 0) throw;
        throw InvalidInput(prefix + error.key(), error.value(), error.rule());
    }
}

}  // namespace mdr::io
