#include "hikari/methods/method_catalog.h"

#include <string>
#include <variant>

#include "hikari/methods/method_option_text.h"
#include "hikari/methods/method_options.h"
#include "hikari/methods/registry.h"
#include "hikari/shading/shading_terms.h"

namespace hikari {

namespace {

using Json = nlohmann::json;

/// What values an option takes: its kind and its range or words.
struct OptionValues {
    Json& out;
    void operator()(const IntegerOption& o) const { range("integer", o.min, o.max); }
    void operator()(const OptionalIntegerOption& o) const { range("integer", o.min, o.max); }
    void operator()(const RealOption& o) const { range("real", o.min, o.max); }
    void operator()(const ColorOption&) const { out["kind"] = "color"; }
    template <class T>
    void operator()(const ChoiceOption<T>& o) const {
        out["kind"] = "choice";
        out["choices"] = Json::array();
        for (const Choice<T>& c : o.choices) out["choices"].push_back(std::string(c.name));
    }
    template <class N>
    void range(const char* kind, N min, N max) const {
        out["kind"] = kind;
        out["min"] = min;
        out["max"] = max;
    }
};

Json method_data(const Method& method) {
    Json out = {{"name", method.name}, {"summary", method.summary}};
    out["options"] = Json::array();
    for (const MethodOption& option : method.options) {
        Json o = {
            {"name", option_keyword(option.flag)}, {"flag", option.flag}, {"help", option.help}};
        std::visit(OptionValues{o}, option.value);
        out["options"].push_back(std::move(o));
    }
    out["aovs"] = Json::array();
    for (const Choice<Aov>& a : k_aov_choices) {
        if ((shading_term_of(a.value) && !method.shading_terms) ||
            (is_algorithm_aov(a.value) && !has_algorithm_aov(method, a.value)))
            continue;
        out["aovs"].push_back(std::string(a.name));
    }
    out["draws_lines"] = method.draw != nullptr;
    out["explain"] = {{"pixel", method.explain.pixel != nullptr},
                      {"row", method.explain.row != nullptr},
                      {"whole", method.explain.whole != nullptr}};
    return out;
}

}  // namespace

Json method_catalog() {
    Json all = Json::array();
    for (const Method& method : methods()) all.push_back(method_data(method));
    return all;
}

}  // namespace hikari
