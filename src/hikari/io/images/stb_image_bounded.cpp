#include "hikari/io/images/stb_image_bounded.h"

#include <cstdlib>
#include <limits>

#include "hikari/io/images/image_read.h"

namespace {

/// The cap of the innermost AllocationCap on this thread (no cap outside one).
thread_local size_t t_allocation_cap = std::numeric_limits<size_t>::max();
thread_local bool t_cap_exceeded = false;

void* bounded_malloc(size_t bytes) {
    if (bytes > t_allocation_cap) {
        t_cap_exceeded = true;
        return nullptr;
    }
    return std::malloc(bytes);
}

void* bounded_realloc(void* p, size_t bytes) {
    if (bytes > t_allocation_cap) {
        t_cap_exceeded = true;
        return nullptr;
    }
    return std::realloc(p, bytes);
}

}  // namespace

// stb_image's own build, private to this file (STB_IMAGE_STATIC): only the formats hikari hands
// it, sides up to read_image()'s limit, allocations through the cap above.
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_HDR
#define STBI_NO_STDIO
#define STBI_MAX_DIMENSIONS (hikari::k_max_image_side)
#define STBI_MALLOC(size) bounded_malloc(size)
#define STBI_REALLOC(p, size) bounded_realloc(p, size)
#define STBI_FREE(p) std::free(p)
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace hikari::stb {

AllocationCap::AllocationCap(size_t max_bytes) : m_previous(t_allocation_cap) {
    t_allocation_cap = max_bytes;
    t_cap_exceeded = false;
}

AllocationCap::~AllocationCap() { t_allocation_cap = m_previous; }

bool AllocationCap::exceeded() const { return t_cap_exceeded; }

bool info(const unsigned char* data, int size, int* width, int* height, int* channels) {
    return stbi_info_from_memory(data, size, width, height, channels) != 0;
}

bool is_16_bit(const unsigned char* data, int size) {
    return stbi_is_16_bit_from_memory(data, size) != 0;
}

unsigned char* load_8(const unsigned char* data, int size, int* w, int* h, int* channels,
                      int channels_wanted) {
    return stbi_load_from_memory(data, size, w, h, channels, channels_wanted);
}

unsigned short* load_16(const unsigned char* data, int size, int* w, int* h, int* channels,
                        int channels_wanted) {
    return stbi_load_16_from_memory(data, size, w, h, channels, channels_wanted);
}

float* load_float(const unsigned char* data, int size, int* w, int* h, int* channels,
                  int channels_wanted) {
    return stbi_loadf_from_memory(data, size, w, h, channels, channels_wanted);
}

void image_free(void* pixels) { stbi_image_free(pixels); }

const char* failure_reason() { return stbi_failure_reason(); }

}  // namespace hikari::stb
