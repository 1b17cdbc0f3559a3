#include "hikari/session/request_json.h"

#include <algorithm>
#include <string>
#include <vector>

#include "hikari/core/error.h"
#include "hikari/io/scene/json_reader.h"
#include "hikari/io/scene/scene_json.h"
#include "hikari/methods/method_option_text.h"
#include "hikari/methods/method_options.h"

namespace hikari {

namespace {

using Json = nlohmann::json;

/// The keys of a render request, the caller's own after them.
std::vector<std::string_view> request_keys(std::span<const std::string_view> extra) {
    std::vector<std::string_view> keys = {"method", "width", "height", "aov", "camera", "options"};
    keys.insert(keys.end(), extra.begin(), extra.end());
    return keys;
}

}  // namespace

RenderRequest render_request_from_json(const Json& body, std::string_view what,
                                       std::span<const std::string_view> extra_keys) {
    const JsonNode root(body, std::string(what), "");
    const std::vector<std::string_view> keys = request_keys(extra_keys);
    if (!body.is_object()) root.fail("expected a JSON object");
    for (const auto& [key, value] : body.items())
        if (std::find(keys.begin(), keys.end(), key) == keys.end())
            root.at(key).fail("unknown key");
    RenderRequest request;
    if (root.has("method")) request.method = root.at("method").as_string();
    const Method& method = method_named(request.method);
    if (root.has("width")) request.width = root.at("width").as_int(1, 65536);
    if (root.has("height")) request.height = root.at("height").as_int(1, 65536);
    if (root.has("aov")) {
        const JsonNode node = root.at("aov");
        const std::optional<Aov> aov = choice_value<Aov>(k_aov_choices, node.as_string());
        if (!aov)
            node.fail(
                "not an AOV (color, depth, id, normal, ambient, diffuse, specular, "
                "overdraw, paint-order, spans, culled)");
        request.aov = *aov;
    }
    if (root.has("camera")) request.camera = parse_camera(root.at("camera"));
    if (root.has("options")) {
        const JsonNode options = root.at("options");
        if (!options.value().is_object()) options.fail("expected an object of method options");
        for (const auto& [name, value] : options.value().items()) {
            const JsonNode node = options.at(name);
            try {
                set_method_option(request.options, method, name, option_text_of_json(node.value()));
            } catch (const InputError& e) {
                node.fail(e.what());
            }
        }
    }
    return request;
}

ExplainStep explain_step_from_json(const Json& body, std::string_view what) {
    const JsonNode root(body, std::string(what), "");
    ExplainStep step;
    if (root.has("pixel")) {
        const JsonNode pixel = root.at("pixel");
        pixel.expect_array(2);
        step.pixel =
            std::pair{pixel.at(size_t{0}).as_int(0, 65535), pixel.at(size_t{1}).as_int(0, 65535)};
    }
    if (root.has("row")) step.row = root.at("row").as_int(0, 65535);
    return step;
}

}  // namespace hikari
