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

/// How many bytes of a token quote_token() shows before it cuts it: of a word or number, and of
/// a file name (longer, so that the name at its end stays readable in most paths).
inline constexpr size_t k_quoted_token_bytes = 40;
inline constexpr size_t k_quoted_path_bytes = 200;

/// `token` quoted for a message, as printable_text() makes it: 'TOKEN', with `quote` '"'
/// "TOKEN", with '\0' TOKEN alone (a file name or argument that opens the message). A token
/// longer than `max_bytes` is cut there (at a character boundary) and
/// its size said, '123456…' (200000000 bytes), so a 200 MB number in a file makes a one-line
/// message. Every message quoting a name, word or value from an input goes through it.
std::string quote_token(std::string_view token, char quote = '\'',
                        size_t max_bytes = k_quoted_token_bytes);

}  // namespace hikari
