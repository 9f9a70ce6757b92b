#pragma once
// Encoding numbered frames into a video with ffmpeg (a separate program, the Debian package
// `ffmpeg`; marble links no codec). The container follows the output's extension: .mp4 (H.264),
// .webm (VP9) or .webp (animated WebP, looping).
#include <filesystem>
#include <string>

namespace marble {

// Throws InputError("--video") for an extension other than .mp4, .webm or .webp, and
// EnvironmentError (one line saying what to install) when ffmpeg is not on PATH: both before
// any frame is rendered.
void checkVideoOutput(const std::string& output);

// Encodes `frames` files named by the printf pattern `framePattern` (e.g. "frames/frame_%04d.png",
// counted from 0) at `fps` into `output`, written atomically (ffmpeg writes a temporary, which is
// then put in place through writeFileAtomically). Throws EnvironmentError with ffmpeg's first
// error line when it fails.
void encodeVideo(const std::string& framePattern, int frames, int fps, const std::filesystem::path& output);

}  // namespace marble
