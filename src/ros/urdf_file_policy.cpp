#include "rigid_body_sim/ros/urdf_file_policy.h"

#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>

#include <ros/package.h>

#include "rigid_body_sim/ros/regular_file.h"
#include "rigid_body_sim/ros/scene_error.h"
#include "rigid_body_sim/ros/urdf_body.h"

namespace rigid_body_sim {
namespace {

namespace fs = std::filesystem;

const std::string kPackageScheme = "package://";

std::string Quoted(const std::string& text) { return "'" + text + "'"; }

std::string Named(const std::string& written) { return "urdf.file " + Quoted(written); }

struct PackageUrl {
  std::string package;
  std::string rest;  // the path inside the package, without its leading '/'
};

// package://PACKAGE/PATH split, or nullopt for any other path. Throws
// SceneError for a package URL without a package or a path.
std::optional<PackageUrl> SplitPackageUrl(const std::string& path) {
  if (path.compare(0, kPackageScheme.size(), kPackageScheme) != 0) return std::nullopt;
  const std::string rest = path.substr(kPackageScheme.size());
  const std::size_t slash = rest.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == rest.size()) {
    throw SceneError(Named(path) + ": a package URL must be package://PACKAGE/PATH");
  }
  return PackageUrl{rest.substr(0, slash), rest.substr(slash + 1)};
}

std::string PackageDirectory(const std::string& written, const std::string& package) {
  std::string directory = ros::package::getPath(package);
  if (directory.empty()) {
    throw SceneError(Named(written) + ": package " + Quoted(package) + " is not found");
  }
  return directory;
}

// A path ~spawn_body may not read: refused before anything is opened, and in
// the same words whether the file exists or not.
SceneError Refused(const std::string& written) {
  return SceneError(Named(written) +
                    ": ~spawn_body reads only files inside a package (package://) or under a "
                    "directory of ~spawn_file_roots");
}

// Whether `path` is `directory` or below it, component by component (both
// absolute and lexically normal).
bool IsUnder(const fs::path& path, const fs::path& directory) {
  auto component = path.begin();
  for (const fs::path& part : directory) {
    if (part.empty()) continue;  // the empty last part of a trailing '/'
    if (component == path.end() || *component != part) return false;
    ++component;
  }
  return true;
}

// The path with every link, '.' and '..' resolved; nullopt with errno set
// when it does not resolve (a component missing or not to be searched).
std::optional<fs::path> RealPath(const fs::path& path) {
  char resolved[PATH_MAX];
  if (::realpath(path.c_str(), resolved) == nullptr) return std::nullopt;
  return fs::path(resolved);
}

}  // namespace

std::string ResolveUrdfPath(const std::string& path) {
  if (const std::optional<PackageUrl> url = SplitPackageUrl(path)) {
    return PackageDirectory(path, url->package) + "/" + url->rest;
  }
  if (path.empty() || path[0] != '/') {
    throw SceneError(Named(path) + " must be an absolute path or package://PACKAGE/PATH");
  }
  return path;
}

UrdfFilePolicy UrdfFilePolicy::AnyPath() { return UrdfFilePolicy(true, {}); }

UrdfFilePolicy UrdfFilePolicy::UnderRoots(std::vector<std::string> roots) {
  return UrdfFilePolicy(false, std::move(roots));
}

std::string UrdfFilePolicy::Read(const std::string& written) const {
  if (any_path_) return ReadRegularFile(ResolveUrdfPath(written), kMaxUrdfBytes, Named(written));
  return ReadConfined(written);
}

std::string UrdfFilePolicy::ReadConfined(const std::string& written) const {
  fs::path candidate;
  // Where the path, written and resolved, must lead: the package's directory
  // or a root, each as written and with its links resolved.
  std::vector<fs::path> directories;
  if (const std::optional<PackageUrl> url = SplitPackageUrl(written)) {
    const fs::path inside = fs::path(url->rest).lexically_normal();
    if (inside.is_absolute() || inside.empty() || *inside.begin() == "..") throw Refused(written);
    const fs::path directory = PackageDirectory(written, url->package);
    candidate = directory / inside;
    directories.push_back(directory.lexically_normal());
  } else {
    ResolveUrdfPath(written);  // absolute, or the form's error
    candidate = fs::path(written).lexically_normal();
    for (const std::string& root : roots_) directories.push_back(fs::path(root).lexically_normal());
  }
  for (std::size_t i = 0, written_count = directories.size(); i < written_count; ++i) {
    if (const std::optional<fs::path> real = RealPath(directories[i])) directories.push_back(*real);
  }
  auto under_one = [&directories](const fs::path& path) {
    for (const fs::path& directory : directories) {
      if (IsUnder(path, directory)) return true;
    }
    return false;
  };
  if (!under_one(candidate)) throw Refused(written);
  // Inside, as written: whether it exists may be told from here on.
  const std::optional<fs::path> real = RealPath(candidate);
  if (!real) throw SceneError(Named(written) + " cannot be read: " + std::strerror(errno));
  if (!under_one(*real)) throw Refused(written);
  // No link is left in `real`: one in its place now is not followed.
  return ReadRegularFile(real->string(), kMaxUrdfBytes, Named(written), LastLink::kRefuse);
}

void CheckSpawnFileRoots(const std::vector<std::string>& roots) {
  for (std::size_t i = 0; i < roots.size(); ++i) {
    const std::string entry = "~spawn_file_roots[" + std::to_string(i) + "] " + Quoted(roots[i]);
    if (roots[i].empty() || roots[i][0] != '/') {
      throw SceneError(entry + " must be an absolute path");
    }
    struct stat status {};
    if (::stat(roots[i].c_str(), &status) != 0) {
      throw SceneError(entry + " cannot be used: " + std::strerror(errno));
    }
    if (!S_ISDIR(status.st_mode)) throw SceneError(entry + " is not a directory");
  }
}

}  // namespace rigid_body_sim
