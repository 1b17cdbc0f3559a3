#pragma once
// Input text echoed into an error message, made safe for a terminal: a message quotes names,
// tokens and words from the file, and raw control bytes or broken UTF-8 in them would garble the
// one `hikari: error:` line (or move the cursor, ring the bell, ...).

#include <string>
#include <string_view>

namespace hikari {

/// `text` with every byte that is not printable shown as `\xNN` (two hex digits): control
/// characters (below 0x20, and 0x7f) and bytes that are not part of well-formed UTF-8. Printable
/// ASCII and well-formed UTF-8 (accented file names) pass unchanged.
std::string printable_text(std::string_view text);

}  // namespace hikari
