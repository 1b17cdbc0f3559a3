// Method options from text and JSON (methods/method_option_text.h), as the viewer's requests and
// the Python module's keywords give them.
#include "hikari/methods/method_option_text.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "hikari/core/error.h"
#include "hikari/session/session.h"

namespace hikari {
namespace {

using nlohmann::json;

TEST(MethodOptionText, JsonValuesReadAsTheCommandLineWritesThem) {
    EXPECT_EQ(option_text_of_json(json(16)), "16");
    EXPECT_EQ(option_text_of_json(json(0.5)), "0.5");
    EXPECT_EQ(option_text_of_json(json("map")), "map");
    EXPECT_EQ(option_text_of_json(json::parse("[0.1, 0.2, 3]")), "0.1,0.2,3");
}

TEST(MethodOptionText, OtherJsonIsRefused) {
    for (const char* text : {"true", "null", "{}", R"([1, "a"])", "[[1]]"})
        EXPECT_THROW(option_text_of_json(json::parse(text)), InputError) << text;
}

TEST(MethodOptionText, AnOptionSetFromJsonTextTakesTheRegistryRanges) {
    const Method& path = method_named("path");
    MethodSettings settings;
    set_method_option(settings, path, "spp", option_text_of_json(json(7)));
    EXPECT_EQ(settings.samples_per_pixel, 7);
    EXPECT_THROW(set_method_option(settings, path, "spp", option_text_of_json(json(-3))),
                 InputError);
}

}  // namespace
}  // namespace hikari
