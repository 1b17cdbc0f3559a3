#pragma once
// Our own pass over an MTL material library before tinyobjloader reads it: tinyobjloader reads a
// malformed number as 0 and keeps no line numbers, so this scan checks every number of the
// statements hikari uses and records the line of each, for messages that point at the line.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hikari {

/// Where one material's statements are in its MTL file.
struct MtlMaterialLines {
    std::string name;
    uint32_t line = 0;                                         ///< the line of its `newmtl`
    std::vector<std::pair<std::string, uint32_t>> statements;  ///< (keyword, line), in order

    /// The line of the last `keyword` statement (tinyobjloader keeps the last), else of newmtl.
    uint32_t line_of(std::string_view keyword) const;
};

/// Checks the numbers of an MTL file's colour statements (Ka, Kd, Ks, Ke, Tf: 1 to 3 numbers),
/// its scalars (Ns, Ni, d, Tr: one number) and `illum` (an integer from 0 to 10), each a finite
/// 32-bit float. Lines split as tinyobjloader splits them (\n, \r\n or a lone \r). Throws
/// InputError "FILE:LINE: ..." for the first bad one; returns the materials in file order.
std::vector<MtlMaterialLines> scan_mtl_text(const std::filesystem::path& file,
                                            std::string_view text);

}  // namespace hikari
