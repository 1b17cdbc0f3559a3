// hikari_psnr A.png B.png: PSNR in dB between two 8-bit images of the same size, over the RGB
// channels of the encoded (sRGB) values, as image-comparison tools report it. Used by
// bench/run.sh to compare hikari's B3 picture with POV-Ray's.
#include <cmath>
#include <cstdio>

#include <stb_image.h>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: hikari_psnr A.png B.png\n");
        return 2;
    }
    int w[2], h[2], n[2];
    unsigned char* img[2];
    for (int k = 0; k < 2; ++k) {
        img[k] = stbi_load(argv[1 + k], &w[k], &h[k], &n[k], 3);
        if (!img[k]) {
            std::fprintf(stderr, "hikari_psnr: cannot read %s\n", argv[1 + k]);
            return 1;
        }
    }
    if (w[0] != w[1] || h[0] != h[1]) {
        std::fprintf(stderr, "hikari_psnr: sizes differ (%dx%d vs %dx%d)\n", w[0], h[0], w[1],
                     h[1]);
        return 1;
    }
    const size_t count = size_t(w[0]) * h[0] * 3;
    double sum = 0;
    for (size_t i = 0; i < count; ++i) {
        const double d = double(img[0][i]) - double(img[1][i]);
        sum += d * d;
    }
    const double mse = sum / double(count);
    std::printf("%.3f\n", mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : INFINITY);
    stbi_image_free(img[0]);
    stbi_image_free(img[1]);
    return 0;
}
