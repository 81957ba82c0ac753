#pragma once
// Files written whole or not at all: the text goes to PATH.tmp in the same directory, which
// is then renamed to PATH, so a reader never sees half a file and a failed write leaves
// nothing behind.
#include <string>

namespace signorini::detail {

// Writes `text` to `path` (its directory created if missing); returns an error message that
// names the file and says what the system said ("No space left on device"), or an empty
// string on success.
std::string tryWriteFileAtomically(const std::string& path, const std::string& text);

// The same, throwing an OutputError with that message.
void writeFileAtomically(const std::string& path, const std::string& text);

}  // namespace signorini::detail
