// Files written whole or not at all, every step checked: the one way the command line, the image
// writer (measure/image_io) and the glTF writer put a file on disk.
#pragma once

#include <string>
#include <string_view>

namespace penumbra::scene {

// Writes `bytes` to `path`. A regular file (a new one, or an existing one, also through a symbolic
// link, which stays a link) is written to a temporary file beside it (`NAME.tmpPID-N`), each write
// and the close checked, then renamed into place: a failure leaves the old file or nothing, never a
// part, and removes the temporary. An existing device or FIFO (/dev/stdout, /dev/full) is written
// in place, each write and the close checked. Returns "" or one line naming the path (through
// printable) and the system's reason: "out.png: cannot write (No space left on device)".
std::string write_file(const std::string& path, std::string_view bytes);

}  // namespace penumbra::scene
