// A file that a scene or a request names, read only if it is a regular file:
// opened without blocking, so that a FIFO with no writer, a terminal or a
// device never holds the thread that reads it, and checked with fstat on the
// descriptor opened, so that nothing is swapped in between.
#pragma once

#include <cstddef>
#include <string>

namespace rigid_body_sim {

// How the file's last path component may be a symbolic link.
enum class LastLink { kFollow, kRefuse };

// The contents of the file at `path`, at most `max_bytes` of them. `what`
// names it in errors (e.g. "urdf.file '/robots/a.urdf'"). Throws SceneError:
// "<what> cannot be read: <reason>" (open, fstat or read fail, a link refused),
// "<what> is not a regular file (a FIFO)" (a directory, a device, a socket),
// "<what> is more than the limit of <max_bytes> bytes".
std::string ReadRegularFile(const std::string& path, std::size_t max_bytes, const std::string& what,
                            LastLink last_link = LastLink::kFollow);

}  // namespace rigid_body_sim
