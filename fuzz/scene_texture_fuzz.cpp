// libFuzzer target: see fuzz_inputs.h for what one input goes through.

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    (void)hikari::fuzz::scene_texture_input(data, size);
    return 0;
}
