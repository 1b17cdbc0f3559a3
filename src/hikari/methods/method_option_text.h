#pragma once
// A method option set from its text, as the command line takes it (`--spp 16`, `--shadows map`,
// `--line-color 0.1,0.1,0.2`), for the front ends that are not a command line: the Python
// module's keyword arguments and the viewer's requests get the registry's ranges and words.

#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "hikari/methods/registry.h"

namespace hikari {

/// The option's name without dashes, words joined by '_': "--light-samples" → "light_samples".
std::string option_keyword(std::string_view flag);

/// Sets `method`'s option `name` ("spp", "light_samples" or "--light-samples") in `settings`
/// from `text`. Throws InputError saying what the option takes, or that `method` has no such
/// option (listing the ones it has).
void set_method_option(MethodSettings& settings, const Method& method, std::string_view name,
                       std::string_view text);

/// An option's value given as JSON (a viewer request's "options", a Python keyword argument) as
/// the command line writes it: 16, 0.5, map, 0.1,0.2,0.3. Throws InputError for anything else
/// (true, null, an object, a list holding other than numbers).
std::string option_text_of_json(const nlohmann::json& value);

}  // namespace hikari
