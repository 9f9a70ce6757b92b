#include "video_encode.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <vector>

#include "marble/core/atomic_file.h"
#include "marble/core/error.h"

extern char** environ;

namespace marble {
namespace {

std::string lowerExtension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

std::optional<std::filesystem::path> findOnPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t colon = std::min(dirs.find(':', start), dirs.size());
    const std::string dir = dirs.substr(start, colon - start);
    start = colon + 1;
    if (dir.empty()) continue;
    const auto candidate = std::filesystem::path(dir) / program;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
  }
  return std::nullopt;
}

// The codec arguments for each container. Sizes are padded to even numbers: 4:2:0 chroma
// (what players expect of H.264 and VP9) halves both dimensions.
std::vector<std::string> codecArguments(const std::string& ext) {
  const std::string even = "pad=ceil(iw/2)*2:ceil(ih/2)*2";
  if (ext == ".mp4") return {"-vf", even, "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf", "18", "-movflags", "+faststart"};
  if (ext == ".webm") return {"-vf", even, "-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p", "-crf", "30", "-b:v", "0"};
  return {"-c:v", "libwebp", "-lossless", "0", "-q:v", "85", "-loop", "0"};  // .webp
}

std::string firstLineOf(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) return line;
  return "no message";
}

}  // namespace

void checkVideoOutput(const std::string& output) {
  const std::string ext = lowerExtension(output);
  if (ext != ".mp4" && ext != ".webm" && ext != ".webp")
    throw InputError("--video", "", "expected a .mp4, .webm or .webp file, got \"" + output + "\"");
  if (!findOnPath("ffmpeg"))
    throw EnvironmentError("--video: ffmpeg is not installed (not on PATH); install the package ffmpeg, or leave out "
                           "--video to write the frames only");
}

void encodeVideo(const std::string& framePattern, int frames, int fps, const std::filesystem::path& output) {
  const auto ffmpeg = findOnPath("ffmpeg");
  if (!ffmpeg) throw EnvironmentError("--video: ffmpeg is not installed (not on PATH)");
  const std::string ext = lowerExtension(output);
  // ffmpeg writes a file of its own: a temporary outside the user's folder, then moved into
  // place through the one atomic routine.
  const auto tmpDir = std::filesystem::temp_directory_path();
  const std::string tag = "marble-video-" + std::to_string(::getpid());
  const auto tmpVideo = tmpDir / (tag + ext);
  const auto tmpLog = tmpDir / (tag + ".log");
  std::vector<std::string> args = {ffmpeg->string(), "-nostdin", "-y", "-loglevel", "error", "-framerate", std::to_string(fps),
                                   "-start_number", "0", "-i", framePattern, "-frames:v", std::to_string(frames)};
  for (auto& a : codecArguments(ext)) args.push_back(std::move(a));
  args.push_back(tmpVideo.string());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, tmpLog.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, ffmpeg->c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  const bool ran = spawned == 0 && ::waitpid(pid, &status, 0) == pid;
  std::error_code ec;
  if (!ran || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string why = ran ? firstLineOf(tmpLog) : "could not start ffmpeg";
    std::filesystem::remove(tmpVideo, ec);
    std::filesystem::remove(tmpLog, ec);
    throw EnvironmentError("--video: ffmpeg failed: " + why);
  }
  std::filesystem::remove(tmpLog, ec);
  std::ifstream in(tmpVideo, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(tmpVideo, ec);
  if (bytes.empty()) throw EnvironmentError("--video: ffmpeg wrote nothing");
  writeFileAtomically(output, bytes);
}

}  // namespace marble
