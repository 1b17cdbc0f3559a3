// hikari.methods(): the registry as Python data, so a script (or a notebook's widget) can list
// every method with its options and buffers, and a new method appears without touching Python.
#include <string>

#include "bindings.h"
#include "hikari/methods/method_option_text.h"
#include "hikari/methods/registry.h"
#include "hikari/shading/shading_terms.h"

namespace hikari::python {

namespace {

/// What values an option takes, as a dict: kind and range or words.
struct OptionValues {
    py::dict& out;
    void operator()(const IntegerOption& o) const { range("integer", o.min, o.max); }
    void operator()(const OptionalIntegerOption& o) const { range("integer", o.min, o.max); }
    void operator()(const RealOption& o) const { range("real", o.min, o.max); }
    void operator()(const ColorOption&) const { out["kind"] = "color"; }
    template <class T>
    void operator()(const ChoiceOption<T>& o) const {
        out["kind"] = "choice";
        py::list words;
        for (const Choice<T>& c : o.choices) words.append(std::string(c.name));
        out["choices"] = words;
    }
    template <class N>
    void range(const char* kind, N min, N max) const {
        out["kind"] = kind;
        out["min"] = min;
        out["max"] = max;
    }
};

py::dict method_data(const Method& method) {
    py::dict out;
    out["name"] = std::string(method.name);
    out["summary"] = std::string(method.summary);
    py::list options;
    for (const MethodOption& option : method.options) {
        py::dict o;
        o["name"] = option_keyword(option.flag);
        o["flag"] = std::string(option.flag);
        o["help"] = std::string(option.help);
        std::visit(OptionValues{o}, option.value);
        options.append(o);
    }
    out["options"] = options;
    py::list aovs;
    for (const Choice<Aov>& a : k_aov_choices) {
        if ((shading_term_of(a.value) && !method.shading_terms) ||
            (is_algorithm_aov(a.value) && !has_algorithm_aov(method, a.value)))
            continue;
        aovs.append(std::string(a.name));
    }
    out["aovs"] = aovs;
    out["draws_lines"] = method.draw != nullptr;
    return out;
}

}  // namespace

void bind_methods(py::module_& m) {
    m.def(
        "methods",
        [] {
            py::list all;
            for (const Method& method : methods()) all.append(method_data(method));
            return all;
        },
        "Every rendering method: name, summary, options (name, help, kind, range or choices) "
        "and the AOVs it renders.");
}

}  // namespace hikari::python
