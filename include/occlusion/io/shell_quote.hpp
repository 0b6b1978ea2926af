#pragma once
// Text as one word of a POSIX shell command line: for the commands the tool
// runs (the study's --segmenter) and those it tells the user to paste (the
// LAZ refusal), where a file name holding $(...) must stay a name.

#include <string>

namespace occlusion {

// `text` in single quotes, each ' in it written '\'': it's -> 'it'\''s'.
// The shell expands nothing inside: $(...), `...`, * and newlines stay text.
std::string shell_quote(const std::string& text);

}  // namespace occlusion
