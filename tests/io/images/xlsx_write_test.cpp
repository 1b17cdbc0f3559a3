// Rendering into Excel (io/xlsx_write.h): the workbook is a valid zip of the four sheets, the
// picture sheet fills one cell per pixel with the pixel's colour, and the channel sheets hold
// the numbers.
#include "hikari/io/images/xlsx_write.h"

#include <zlib.h>

#include <cstring>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "../temp_dir.h"
#include "hikari/core/error.h"
#include "hikari/io/files/read_file.h"
#include "hikari/io/images/image_write.h"

namespace hikari {
namespace {

uint32_t le(const std::vector<uint8_t>& b, size_t at, int bytes) {
    uint32_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | b[at + static_cast<size_t>(i)];
    return v;
}

/// The uncompressed text of entry `name` of the zip archive `zip` ("" when it has none): its
/// central directory gives the sizes and offset; the data is stored or raw deflate.
std::string unzip(const std::vector<uint8_t>& zip, const std::string& name) {
    size_t end = zip.size() - 22;
    while (end > 0 && le(zip, end, 4) != 0x06054b50u) --end;
    const uint32_t entries = le(zip, end + 10, 2);
    size_t at = le(zip, end + 16, 4);
    for (uint32_t e = 0; e < entries; ++e) {
        const uint32_t method = le(zip, at + 10, 2), packed = le(zip, at + 20, 4),
                       size = le(zip, at + 24, 4), name_len = le(zip, at + 28, 2),
                       extra = le(zip, at + 30, 2), comment = le(zip, at + 32, 2),
                       local = le(zip, at + 42, 4);
        const std::string entry(reinterpret_cast<const char*>(zip.data() + at + 46), name_len);
        at += 46 + name_len + extra + comment;
        if (entry != name) continue;
        const size_t data = local + 30 + le(zip, local + 26, 2) + le(zip, local + 28, 2);
        std::string out(size, '\0');
        if (method == 0) {
            std::memcpy(out.data(), zip.data() + data, size);
            return out;
        }
        z_stream s{};
        inflateInit2(&s, -15);
        s.next_in = const_cast<Bytef*>(zip.data() + data);
        s.avail_in = packed;
        s.next_out = reinterpret_cast<Bytef*>(out.data());
        s.avail_out = size;
        const int status = inflate(&s, Z_FINISH);
        inflateEnd(&s);
        EXPECT_EQ(status, Z_STREAM_END) << name;
        return out;
    }
    return "";
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(XlsxWrite, EveryPixelIsACellOfItsColour) {
    Srgb8Image image(3, 2);
    const uint8_t colours[6][3] = {{255, 0, 0},  {0, 255, 0},  {0, 0, 255},
                                   {10, 20, 30}, {10, 20, 30}, {200, 100, 50}};
    for (size_t i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c) image.bytes[3 * i + c] = colours[i][c];
    const std::vector<uint8_t> zip = encode_xlsx("t.xlsx", image);
    ASSERT_GT(zip.size(), 4u);
    EXPECT_EQ(zip[0], 'P');
    EXPECT_EQ(zip[1], 'K');
    const std::string book = unzip(zip, "xl/workbook.xml");
    for (const char* sheet : {"\"image\"", "\"red\"", "\"green\"", "\"blue\""})
        EXPECT_NE(book.find(sheet), std::string::npos) << sheet;
    // Five distinct colours: five solid fills beside the two every workbook has.
    const std::string styles = unzip(zip, "xl/styles.xml");
    for (const char* rgb : {"FFFF0000", "FF00FF00", "FF0000FF", "FF0A141E", "FFC86432"})
        EXPECT_NE(styles.find(rgb), std::string::npos) << rgb;
    EXPECT_NE(styles.find("<fills count=\"7\">"), std::string::npos) << styles;
    const std::string picture = unzip(zip, "xl/worksheets/sheet1.xml");
    EXPECT_EQ(count(picture, "<c r="), 6u);
    EXPECT_NE(picture.find("showGridLines=\"0\""), std::string::npos);
    // The red channel as numbers, row by row.
    const std::string red = unzip(zip, "xl/worksheets/sheet2.xml");
    EXPECT_NE(red.find("<c r=\"A1\"><v>255</v></c><c r=\"B1\"><v>0</v></c>"), std::string::npos)
        << red;
    EXPECT_NE(red.find("<c r=\"C2\"><v>200</v></c>"), std::string::npos) << red;
}

TEST(XlsxWrite, TooLargeForASheetIsRefusedAndNothingIsWritten) {
    const testing::TempDir dir;
    EXPECT_THROW(write_image(dir / "wide.xlsx", Srgb8Image(k_xlsx_max_columns + 1, 1)), InputError);
    EXPECT_EQ(dir.entry_count(), 0u);
    write_image(dir / "ok.xlsx", Image(4, 3, Vec3(0.5f)));
    EXPECT_EQ(read_file_bytes(dir / "ok.xlsx").substr(0, 2), "PK");
}

}  // namespace
}  // namespace hikari
