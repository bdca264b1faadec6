// Writing output files safely: data goes to a temporary file in the target folder and is
// renamed over the target only when complete (STYLE.md, Errors). Used by pictures, PNG
// previews, scene files and meshes; nothing here knows about file formats.
#pragma once

#include <string>

namespace rp {

// Writes `data` to `path` via a temporary sibling file and rename(2). Throws InputError
// naming `path` when the folder is not writable or the disk fills; the temporary file is
// removed on failure.
void writeFileAtomically(const std::string& path, const std::string& data);

}  // namespace rp
