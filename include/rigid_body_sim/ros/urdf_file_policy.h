// Which files a body's `urdf: {file: ..}` may name (doc/security.md). A scene
// loaded at start is the operator's and may name any file; ~spawn_body comes
// from anyone on the ROS graph, so it reads only files inside the package of
// a package:// URL and files under a directory of ~spawn_file_roots. A path it
// may not read is refused before anything is opened, with one message
// whether or not the file exists.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace rigid_body_sim {

// The absolute path of `path`: itself when absolute, the package's directory
// (ros::package::getPath) joined with the rest for package://pkg/rest. Throws
// SceneError naming the path: a relative path, a package:// URL without a
// file part, a package that ROS does not know.
std::string ResolveUrdfPath(const std::string& path);

class UrdfFilePolicy {
 public:
  // Any absolute path or package:// URL: a scene loaded at start.
  static UrdfFilePolicy AnyPath();
  // ~spawn_body's: a package:// URL whose path, with every link resolved,
  // stays inside its package's directory, or an absolute path that, written
  // and with every link resolved, is under one of `roots` (absolute
  // directories, ~spawn_file_roots; none: no absolute path).
  static UrdfFilePolicy UnderRoots(std::vector<std::string> roots);

  // The URDF text of the file `written` names (urdf.file as written), at most
  // kMaxUrdfBytes, read with ReadRegularFile. Throws SceneError ("urdf.file
  // '<written>' ..."): the path's form (ResolveUrdfPath), a path this policy
  // does not read, and ReadRegularFile's errors.
  std::string Read(const std::string& written) const;

 private:
  UrdfFilePolicy(bool any_path, std::vector<std::string> roots)
      : any_path_(any_path), roots_(std::move(roots)) {}

  std::string ReadConfined(const std::string& written) const;

  bool any_path_;
  std::vector<std::string> roots_;
};

// The directories of `~spawn_file_roots` as written, each checked to be an
// absolute path of a directory. Throws SceneError naming the entry.
void CheckSpawnFileRoots(const std::vector<std::string>& roots);

}  // namespace rigid_body_sim
