// The source rule behind gl/checked_calls.h: marble's code reaches a draw, dispatch, clear or blit
// only through the checked functions, so the draw state check (gl/draw_state_check.h) runs before
// every one of them and a new pass cannot forget it. Until session 19 the check was called by hand
// at each site, and one clear (the lighting pass's mirror-hit attachment) had been left out.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace marble {
namespace {

namespace fs = std::filesystem;

// The 1-based lines of `text` that call one of the commands raw. Text after `//` is a comment
// and does not count; glClearColor / glClearDepth(f) / glClearStencil set values and draw nothing;
// the texture clears read no program state (gl/checked_calls.h says why they are left out).
std::vector<int> rawCommandLines(const std::string& text) {
  static const std::regex kRaw(
      R"(\bgl(Draw|MultiDraw|Dispatch|Blit)\w*\s*\(|\bglClear(?!Color|Depth|Stencil|Tex)\w*\s*\()");
  std::vector<int> lines;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string code = line.substr(0, line.find("//"));
    if (std::regex_search(code, kRaw)) lines.push_back(number);
  }
  return lines;
}

TEST(CheckedCalls, TheRuleFindsEveryKindOfRawCommand) {
  // The negative control of the rule below: each raw command is found, on its own line.
  const std::string text =
      "glDrawArrays(GL_TRIANGLES, 0, 3);\n"                    // 1
      "  glDrawElements (GL_TRIANGLES, n, GL_UNSIGNED_INT, 0);\n"  // 2
      "glMultiDrawArraysIndirect(GL_TRIANGLES, 0, 1, 0);\n"    // 3
      "if (x) glDispatchCompute(1, 1, 1);\n"                   // 4
      "glDispatchComputeIndirect(0);\n"                        // 5
      "glClear(GL_COLOR_BUFFER_BIT);\n"                        // 6
      "glClearBufferfv(GL_COLOR, 0, c);\n"                     // 7
      "glClearNamedFramebufferfv(f, GL_DEPTH, 0, &one);\n"     // 8
      "glBlitNamedFramebuffer(a, b, 0, 0, 1, 1, 0, 0, 1, 1, m, f);\n";  // 9
  EXPECT_EQ(rawCommandLines(text), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(CheckedCalls, TheRuleLeavesTheCheckedCallsCommentsAndValueSettersAlone) {
  const std::string text =
      "gl::drawArrays(GL_TRIANGLES, 0, 3);\n"
      "gl::clearFramebuffer(fbo, GL_COLOR, 0, zero);\n"
      "// the merge's glClearTexSubImage(...) waits for image stores\n"
      "x = 1;  // then glDrawArrays(GL_TRIANGLES, 0, 3)\n"
      "glClearColor(0, 0, 0, 1);\n"
      "glClearDepthf(1.0f);\n"
      "glClearStencil(0);\n"
      "glClearTexSubImage(t, 0, 0, 0, 0, 1, 1, 1, f, t, v);\n"
      "myglDraw(3);\n";
  EXPECT_TRUE(rawCommandLines(text).empty());
}

TEST(CheckedCalls, NoRawCommandOutsideThisFile) {
  const fs::path root = fs::path(MARBLE_SOURCE_DIR) / "src";
  const fs::path allowed = root / "marble" / "gl" / "checked_calls.h";
  int filesRead = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::string ext = entry.path().extension().string();
    if (ext != ".cpp" && ext != ".h" && ext != ".hpp") continue;
    if (fs::equivalent(entry.path(), allowed)) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    ASSERT_TRUE(in) << entry.path();
    std::ostringstream text;
    text << in.rdbuf();
    ++filesRead;
    for (int line : rawCommandLines(text.str()))
      ADD_FAILURE() << entry.path().string() << ":" << line
                    << ": a raw GL draw/dispatch/clear/blit; call the gl:: function of gl/checked_calls.h";
  }
  EXPECT_GT(filesRead, 50);  // the walk found the sources
}

}  // namespace
}  // namespace marble
