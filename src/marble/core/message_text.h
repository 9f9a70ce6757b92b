#pragma once
// The one place where text from outside (file content, file names, user strings, library
// messages) is made fit for a one-line message on a terminal: every InputError, every warning
// and every line the CLI prints about a failure goes through printable().
#include <cstddef>
#include <string>
#include <string_view>

namespace marble {

// How long one part of a message (a file name, a value, a library's message) may be.
inline constexpr size_t kMessagePartLimit = 300;
// How long a whole message line may be (it may nest the messages of referenced files).
inline constexpr size_t kMessageLineLimit = 2000;

// `text` with every control character escaped (\n, \r, \t, \0, \e as "\x1b", other C0/C1 controls
// and DEL as \xNN, bytes that are not UTF-8 as \xNN), so that no line break, terminal escape
// sequence or NUL reaches the terminal, and cut to at most `limit` bytes on a character boundary
// with " ... (N bytes in all)" appended. Well-formed UTF-8 (a file named "Würfel.obj") is kept;
// backslashes are kept as they are, so printable(printable(s)) == printable(s) for short s.
std::string printable(std::string_view text, size_t limit = kMessagePartLimit);

// "...": `text` cut to an excerpt of at most `limit` bytes for quoting file content, escaped as
// printable() does, between double quotes.
std::string quotedExcerpt(std::string_view text, size_t limit = 40);

}  // namespace marble
