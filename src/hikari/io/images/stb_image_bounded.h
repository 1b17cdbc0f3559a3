#pragma once
// stb_image (PNG, JPEG and Radiance HDR only) compiled into hikari with every allocation it makes
// checked against a cap the caller sets from the image's header: a PNG whose data inflates to
// far more than its size needs (a decompression bomb) or a JPEG whose markers ask for buffers its
// header does not justify fails cleanly instead of taking the memory. Debian's libstb cannot be
// told so (its malloc is fixed when it is built), so this file builds stb_image itself.

#include <cstddef>

namespace hikari::stb {

/// While alive, every allocation stb_image makes on this thread larger than `max_bytes` fails
/// (stb_image then returns its "outofmem" error, and exceeded() says why).
class AllocationCap {
  public:
    explicit AllocationCap(size_t max_bytes);
    ~AllocationCap();
    AllocationCap(const AllocationCap&) = delete;
    AllocationCap& operator=(const AllocationCap&) = delete;

    /// Whether an allocation was refused because it exceeded the cap.
    bool exceeded() const;

  private:
    size_t m_previous;
};

/// stbi_info_from_memory: the size and channel count from the header; false when unreadable.
bool info(const unsigned char* data, int size, int* width, int* height, int* channels);
/// stbi_is_16_bit_from_memory.
bool is_16_bit(const unsigned char* data, int size);
/// stbi_load_from_memory (8-bit samples), stbi_load_16_from_memory, stbi_loadf_from_memory:
/// `channels_wanted` samples a pixel, null on failure (see failure_reason()).
unsigned char* load_8(const unsigned char* data, int size, int* w, int* h, int* channels,
                      int channels_wanted);
unsigned short* load_16(const unsigned char* data, int size, int* w, int* h, int* channels,
                        int channels_wanted);
float* load_float(const unsigned char* data, int size, int* w, int* h, int* channels,
                  int channels_wanted);
/// Frees what a load function returned.
void image_free(void* pixels);
/// stbi_failure_reason: why the last call on this thread failed.
const char* failure_reason();

}  // namespace hikari::stb
