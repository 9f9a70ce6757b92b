// The bad-input catalogue (docs/bad-inputs.md), one test per row: the bad file or argument is
// made in a temporary folder, `marble` runs there (so messages name files as a user typed them),
// and the test checks the exit code, the message, and that stderr is one line (a warning for the
// rows that succeed, nothing for clean successes).
//
// MARBLE_BAD_INPUTS_TABLE=FILE appends each row as it ran (markdown) to FILE, which is how the
// table in docs/bad-inputs.md is regenerated:
//   MARBLE_BAD_INPUTS_TABLE=/tmp/t.md build/tests/marble_cli_tests --gtest_filter='BadInputs*'
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include "cli_support.h"
#include "marble/core/image.h"
#include "hdr_support.h"

namespace {

namespace fs = std::filesystem;

struct Row {
  const char* name;     // test name
  const char* what;     // the catalogue's "bad input" column
  std::string args;     // after `marble`
  int exitCode;
  std::string message;  // must appear in stderr's first line ("" = stderr must be empty)
  const char* env = "";
  // CLI11's usage errors add "Run with --help ..." as a second line (reported; see the doc).
  bool usageError = false;
};

// gtest prints a failing parameter with this instead of a byte dump.
void PrintTo(const Row& row, std::ostream* os) { *os << row.name; }

std::string u32le(uint32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[static_cast<size_t>(i)] = static_cast<char>((v >> (8 * i)) & 0xFF);
  return s;
}

std::string plyAscii(const std::string& vertexCount, const std::string& body) {
  return "ply\nformat ascii 1.0\nelement vertex " + vertexCount +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
         "property list uchar int vertex_indices\nend_header\n" + body;
}

std::string gltfWith(const std::string& buffers, const std::string& extra = "") {
  return R"({"asset":{"version":"2.0"},"buffers":)" + buffers +
         R"(,"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],)"
         R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
         R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],)"
         R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}])" + extra + "}";
}

// Every file the rows refer to.
void writeInputs(const fs::path& dir) {
  const auto put = [&](const std::string& name, const std::string& bytes) { std::ofstream(dir / name, std::ios::binary) << bytes; };
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  fs::create_directories(dir / "folder.obj");
  put("afile", "not a folder");
  put("empty.obj", "");
  put("empty.ply", "");
  put("noext", tri + "f 1 2 3\n");
  put("model.fbx", std::string("Kaydara FBX Binary  \0\x1a\0", 23));
  put("garbage.obj", std::string("\x7f" "ELF\x02\x01\x01\x00\xff\xfe", 10));
  put("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  put("inf.obj", "v 0 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n");
  put("range.obj", tri + "f 1 2 9\n");
  put("negative.obj", tri + "f 1 2 -7\n");
  put("zero.obj", tri + "f 0 1 2\n");
  put("two.obj", tri + "f 1 2\n");
  put("nofaces.obj", "v 0 0 0\nv 1 0 0\n");
  // Two triangles on the same texture coordinates (bake --uv-from file must refuse them).
  put("overlapuv.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 1\nvt 0 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/2\n");
  put("point.obj", "v 1 1 1\nv 1 1 1\nv 1 1 1\nf 1 2 3\n");
  put("degenerate.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 4 4 4\n");
  put("zeroarea.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  put("truncated.ply", plyAscii("3", "0 0 0\n1 0 0\n"));
  put("notply.ply", "hello\n");
  put("huge.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 2147483648\nproperty float x\nproperty float y\n"
                  "property float z\nend_header\n" + std::string(16, '\0'));
  put("index.ply", plyAscii("3", "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n"));
  put("negindex.ply", plyAscii("3", "0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n"));
  put("billion.stl", std::string(80, 'x') + u32le(1'000'000'000) + std::string(50, '\0'));
  put("lying.stl", std::string(80, 'x') + u32le(40'000'000) + std::string(50, '\0'));
  put("short.stl", std::string(40, 'x'));
  put("nan.stl", "solid x\nfacet normal 0 0 0\nouter loop\nvertex nan 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n");
  put("length.glb", "glTF" + u32le(2) + u32le(0xFFFFFFFFu) + std::string(16, '\0'));
  put("chunk.glb", "glTF" + u32le(2) + u32le(28) + u32le(0xFFFFFFF0u) + u32le(0x4E4F534Au) + "{}  ");
  put("notglb.glb", "GLTF" + std::string(20, '\0'));
  put("cut.gltf", R"({"asset": {"version": "2.0"}, "meshes": [)");
  put("nomesh.gltf", R"({"asset": {"version": "2.0"}})");
  put("v1.gltf", R"({"asset": {"version": "1.0"}})");
  put("missingbin.gltf", gltfWith(R"([{"uri":"missing.bin","byteLength":42}])"));
  put("url.gltf", gltfWith(R"([{"uri":"http://example.com/a.bin","byteLength":42}])"));
  // Three vertices and the indices 0 1 9.
  put("index.gltf", gltfWith(R"([{"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAkA","byteLength":42}])"));
  put("overflow.gltf", gltfWith(R"([{"uri":"missing.bin","byteLength":42}])", R"(,"extras":{"big":1e400})"));
  put("cut.json", R"({"mesh": )");
  put("blank.json", " \n");
  put("array.json", "[1, 2]");
  put("fovtype.json", R"({"camera": {"fov_y_deg": "wide"}})");
  put("fovrange.json", R"({"camera": {"fov_y_deg": 500}})");
  put("camnumber.json", R"({"camera": 5})");
  put("wide.json", R"({"render": {"width": 100000}})");
  put("halfpixel.json", R"({"render": {"width": 64.5}})");
  put("negwidth.json", R"({"render": {"width": -1}})");
  put("nanliteral.json", R"({"camera": {"position": [NaN, 0, 1]}})");
  put("overflow.json", R"({"light": {"intensity": 1e400}})");
  put("far.json", R"({"camera": {"position": [0, 0, 1e39]}})");
  put("unknown.json", R"({"render": {"width": 16, "height": 16, "colour": 1}})");
  put("mode.json", R"({"render": {"mode": "sparkly"}})");
  put("antialias.json", R"({"render": {"antialias": "msaa"}})");
  put("up.json", R"({"up": "w"})");
  put("parallel.json", R"({"camera": {"position": [0, 2, 0], "up": [0, 1, 0]}})");
  put("lightorigin.json", R"({"light": {"position": [0, 0, 0]}})");
  put("spot.json", R"({"light": {"type": "spot"}})");
  put("meshmissing.json", R"({"mesh": "nothere.obj"})");
  put("teapot.json", R"({"mesh": "builtin:teapot"})");
  put("mattype.json", R"({"material": {"turb_power": "x"}})");
  put("matrange.json", R"({"material": {"turb_power": -5}})");
  put("granite.json", R"({"material": {"preset": "granite"}})");
  put("preset_type.json", R"({"turb_power": [1, 2]})");
  put("preset_cycle.json", R"({"preset": "preset_cycle.json"})");
  put("preset_overflow.json", R"({"turb_power": 1e400})");
  // Shader folders for MARBLE_SHADER_DIR: one file each, the rest stays built in.
  fs::create_directories(dir / "brokenshaders");
  put("brokenshaders/lighting.frag.glsl", "#version 450 core\nout vec4 o;\nvoid main() { o = vec4(undeclared_thing); }\n");
  fs::create_directories(dir / "brokeninclude");
  put("brokeninclude/post.frag.glsl", "#version 450 core\n#include \"nothere.glsl\"\nvoid main() {}\n");
  // Environment maps (Radiance .hdr).
  marble::test::writeHdrFile(dir / "sky.hdr", marble::test::syntheticSky(64));
  put("garbage.hdr", std::string("\x7f" "ELF\x02\x01\x01\x00\xff\xfe", 10));
  const std::string rle = marble::test::encodeHdr(marble::test::syntheticSky(64));
  put("cut.hdr", rle.substr(0, rle.size() - 1));
  put("square.hdr", marble::test::encodeHdr(marble::test::constantImage(32, 32, glm::vec3(1.0f))));
  put("huge.hdr", marble::test::hdrHeader(20000, 10000) + std::string(64, '\x80'));
  put("envmissing.json", R"({"render": {"environment_map": "nothere.hdr"}})");
  put("envnofile.json", R"({"render": {"environment": "map"}})");
  // A valid 1x1 PNG without text chunks (written as marble writes one, without a scene).
  marble::writePng(dir / "plain.png", marble::ImageRGBA8{1, 1, {0, 0, 0, 255}});
  put("notpng.png", "just text");
  put("groundtype.json", R"({"render": {"ground": "yes"}})");
  put("envsky.json", R"({"render": {"environment": "sky"}})");
  // Issue 18: hostile inputs.
  ::mkfifo((dir / "pipe.obj").c_str(), 0644);
  ::mkfifo((dir / "pipe.bin").c_str(), 0644);
  ::mkfifo((dir / "pipe.png").c_str(), 0644);
  put("fifomesh.json", R"({"mesh": "pipe.obj"})");
  put("fifobuffer.gltf", gltfWith(R"([{"uri":"pipe.bin","byteLength":42}])"));
  fs::create_symlink("loop2.obj", dir / "loop1.obj");
  fs::create_symlink("loop1.obj", dir / "loop2.obj");
  fs::create_symlink("gone.obj", dir / "dangling.obj");
  {
    std::string nodes = "[";
    for (int i = 0; i < 40; ++i) nodes += "{\"children\":[" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]},";
    put("dag.gltf", gltfWith(R"([{"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIA","byteLength":42}])", ",\"nodes\":" + nodes + "{\"mesh\":0}]"));
  }
  const std::string deep = std::string(100'000, '[') + std::string(100'000, ']');
  put("deep.json", "{\"camera\": " + deep + "}");
  put("deep.gltf", R"({"asset":{"version":"2.0"},"extras":)" + deep + "}");
  put("hugestring.json", "{\"camera\": {\"fov_y_deg\": \"" + std::string(10'000'000, 'A') + "\"}}");
  put("credentials.json", "root:$6$secretHASH:19000:0:99999:7:::\n");
  put("passwd.gltf", gltfWith(R"([{"uri":"/etc/passwd","byteLength":42}])"));
  put("updir.gltf", gltfWith(R"([{"uri":"../../../../etc/passwd","byteLength":42}])"));
  {
    std::string copies = tri;
    for (int i = 0; i < 100'000; ++i) copies += "f 1 2 3\n";
    put("copies.obj", copies);
  }
  put("sparse.stl", std::string(84, '\0'));
  fs::resize_file(dir / "sparse.stl", 3'900'000'000ull);
  put("esc\x1b[31mred.obj", tri + "f 1 2\n");
  put("escape.obj", tri + "f 1 2 \x1b]0;pwned\x07\n");
  put("sceneobj.json", R"({"mesh": "two.obj"})");
}

const std::string kSmall = " -o out.png --width 16 --height 16";

const std::vector<Row>& rows() {
  static const std::vector<Row> r = {
      // Mesh files: existence and format.
      {"MissingFile", "mesh file does not exist", "render missing.obj" + kSmall, 2, "marble render: missing.obj: file not found"},
      {"Directory", "mesh path is a directory", "render folder.obj" + kSmall, 2, "marble render: folder.obj: is a directory, not a mesh file"},
      {"EmptyObj", "empty OBJ", "render empty.obj" + kSmall, 2, "marble render: empty.obj: file is empty"},
      {"EmptyPly", "empty PLY", "render empty.ply" + kSmall, 2, "marble render: empty.ply: file is empty"},
      {"NoExtension", "no file extension", "render noext" + kSmall, 2, "marble render: noext: unknown mesh format '(no extension)'"},
      {"UnknownFormat", "unsupported format (.fbx)", "render model.fbx" + kSmall, 2, "marble render: model.fbx: unknown mesh format '.fbx'"},
      {"BinaryGarbageObj", "binary garbage named .obj", "render garbage.obj" + kSmall, 2,
       "marble render: garbage.obj: byte 7: binary data (NUL byte) in what should be a text OBJ file"},
      // OBJ contents.
      {"NanCoordinate", "NaN coordinate (OBJ)", "render nan.obj" + kSmall, 2, "marble render: nan.obj: line 2: 'v': number is NaN or infinite ('nan')"},
      {"InfCoordinate", "infinite coordinate (OBJ)", "render inf.obj" + kSmall, 2, "marble render: inf.obj: line 2: 'v': number is NaN or infinite ('inf')"},
      {"IndexOutOfRange", "face index past the last vertex (OBJ)", "render range.obj" + kSmall, 2,
       "marble render: range.obj: line 4: vertex index 9 is out of range (the file has 3 vertices)"},
      {"NegativeIndexOutOfRange", "negative (relative) index too far back (OBJ)", "render negative.obj" + kSmall, 2,
       "marble render: negative.obj: line 4: relative vertex index -7 is out of range (only 3 vertices defined so far)"},
      {"ZeroIndex", "index 0 (OBJ counts from 1)", "render zero.obj" + kSmall, 2,
       "marble render: zero.obj: line 4: vertex index 0 is invalid (OBJ indices start at 1)"},
      {"TwoVertexFace", "face with 2 vertices (OBJ)", "render two.obj" + kSmall, 2, "marble render: two.obj: line 4: face has 2 vertices; a face needs at least 3"},
      {"NoFaces", "vertices but no faces (OBJ)", "render nofaces.obj" + kSmall, 2, "marble render: nofaces.obj: no triangles: the file has 2 vertices but no faces"},
      {"ZeroExtent", "all vertices at one point", "render point.obj" + kSmall, 2,
       "marble render: point.obj: bounds: all vertices are at the same point (zero extent); cannot normalize"},
      {"DegenerateFace", "a degenerate face (f 4 4 4) beside a good one: accepted, it adds nothing", "render degenerate.obj" + kSmall, 0, ""},
      {"ZeroAreaFace", "only a zero-area (collinear) face: accepted, renders nothing visible", "render zeroarea.obj" + kSmall, 0, ""},
      // PLY.
      {"TruncatedPly", "PLY body shorter than its header says", "render truncated.ply" + kSmall, 2,
       "marble render: truncated.ply: header line 3: declares 3 vertex elements (at least 18 bytes) but only 12 bytes follow the header (truncated file?)"},
      {"NotPly", "text that is not PLY, named .ply", "render notply.ply" + kSmall, 2, "marble render: notply.ply: header: not a PLY file (it must start with a line 'ply')"},
      {"HugePlyCount", "PLY declaring 2^31 vertices", "render huge.ply" + kSmall, 2,
       "marble render: huge.ply: header line 3: declares 2,147,483,648 vertices; the limit is 50,000,000"},
      {"PlyIndexOutOfRange", "PLY face index past the last vertex", "render index.ply" + kSmall, 2,
       "marble render: index.ply: line 13: face 0: vertex index 5 is out of range (the file has 3 vertices)"},
      {"PlyNegativeIndex", "PLY negative face index", "render negindex.ply" + kSmall, 2,
       "marble render: negindex.ply: line 13: face 0: vertex index -1 is out of range (the file has 3 vertices)"},
      // STL.
      {"StlBillionTriangles", "binary STL declaring 10^9 triangles", "render billion.stl" + kSmall, 2,
       "marble render: billion.stl: byte 80: declares 1,000,000,000 triangles; the limit is 50,000,000"},
      {"StlLyingCount", "binary STL declaring 40 million triangles in 134 bytes", "render lying.stl" + kSmall, 2,
       "marble render: lying.stl: byte 80: declares 40,000,000 triangles (2,000,000,084 bytes) but the file has only 134 bytes (truncated)"},
      {"StlTooShort", "STL shorter than the binary header", "render short.stl" + kSmall, 2,
       "marble render: short.stl: header: file is 40 bytes, too short for a binary STL (at least 84) and not ASCII STL ('solid ...')"},
      {"StlNan", "NaN vertex (ASCII STL)", "render nan.stl" + kSmall, 2, "marble render: nan.stl: line 4: coordinate is NaN or infinite"},
      // glTF / GLB.
      {"GlbHugeLength", "GLB header declaring 4 GiB", "render length.glb" + kSmall, 2,
       "marble render: length.glb: header: declares 4,294,967,295 bytes but the file has 28 (truncated)"},
      {"GlbHugeChunk", "GLB JSON chunk length past the file", "render chunk.glb" + kSmall, 2,
       "marble render: chunk.glb: header: declares 28 bytes but the file has 24 (truncated)"},
      {"NotGlb", "GLB with the wrong magic", "render notglb.glb" + kSmall, 2, "marble render: notglb.glb: header: not a GLB file (it must start with 'glTF')"},
      {"TruncatedGltf", "glTF JSON cut short", "render cut.gltf" + kSmall, 2,
       "marble render: cut.gltf: byte 41: invalid JSON: syntax error while parsing value - unexpected end of input"},
      {"GltfNoMeshes", "glTF without meshes", "render nomesh.gltf" + kSmall, 2, "marble render: nomesh.gltf: json: no meshes"},
      {"GltfVersion1", "glTF 1.0", "render v1.gltf" + kSmall, 2, "marble render: v1.gltf: asset: glTF version \"1.0\" is not supported (need 2.x)"},
      {"GltfMissingBuffer", "glTF buffer file missing", "render missingbin.gltf" + kSmall, 2,
       "marble render: missingbin.gltf: buffer 0: cannot read 'missing.bin': missing.bin: file not found"},
      {"GltfUrlBuffer", "glTF buffer at an http:// URL", "render url.gltf" + kSmall, 2,
       "marble render: url.gltf: buffer 0: external URL 'http://example.com/a.bin' is not supported (only files)"},
      {"GltfIndexOutOfRange", "glTF index past the last vertex", "render index.gltf" + kSmall, 2,
       "marble render: index.gltf: accessor 1: index 9 (element 2) is out of range (POSITION has 3)"},
      // Regression (found by fuzz_gltf): a number too large for a double escaped as a raw
      // nlohmann exception with exit code 1. Fails until gltf_loader.cpp catches it (report).
      {"GltfNumberOverflow", "glTF with a number beyond double (1e400)", "render overflow.gltf" + kSmall, 2, "marble render: overflow.gltf: "},
      // Scene JSON.
      {"SceneTruncated", "scene JSON cut short", "render cut.json" + kSmall, 2,
       "marble render: cut.json: invalid JSON: parse error at line 1, column 10: syntax error while parsing value - unexpected end of input"},
      {"SceneBlank", "scene file of whitespace", "render blank.json" + kSmall, 2, "marble render: blank.json: empty file"},
      {"SceneNotObject", "scene JSON is an array", "render array.json" + kSmall, 2, "marble render: array.json: expected a JSON object at the top level"},
      {"SceneWrongType", "string where a number belongs", "render fovtype.json" + kSmall, 2,
       "marble render: fovtype.json: camera.fov_y_deg: expected a number, got string \"wide\""},
      {"SceneOutOfRange", "field of view 500 degrees", "render fovrange.json" + kSmall, 2,
       "marble render: fovrange.json: camera.fov_y_deg: expected a number in [1, 179], got 500"},
      {"SceneObjectIsNumber", "number where an object belongs", "render camnumber.json" + kSmall, 2,
       "marble render: camnumber.json: camera: expected an object, got number 5"},
      {"SceneAbsurdSize", "render width 100000 in the scene", "render wide.json -o out.png", 2,
       "marble render: wide.json: render.width: expected a whole number in [1, 8192], got 100000"},
      {"SceneFractionalSize", "render width 64.5", "render halfpixel.json -o out.png", 2,
       "marble render: halfpixel.json: render.width: expected a whole number, got number 64.5"},
      {"SceneNegativeSize", "render width -1", "render negwidth.json -o out.png", 2,
       "marble render: negwidth.json: render.width: expected a whole number in [1, 8192], got -1"},
      {"SceneNanLiteral", "NaN in scene JSON (not JSON)", "render nanliteral.json" + kSmall, 2,
       "marble render: nanliteral.json: invalid JSON: parse error at line 1, column 26"},
      // Regression (found by fuzz_scene): see GltfNumberOverflow. Fails until scene_io.cpp (loadSceneText) catches it.
      {"SceneNumberOverflow", "number beyond double (1e400) in a scene", "render overflow.json" + kSmall, 2, "marble render: overflow.json: "},
      {"SceneHugeCoordinate", "camera at 1e39", "render far.json" + kSmall, 2,
       "marble render: far.json: camera.position: component 2 must be in [-10000, 10000], got 1e+39"},
      {"SceneUnknownKey", "unknown key: a warning, the render goes on", "render unknown.json -o out.png", 0,
       "warning: unknown.json: render.colour: unknown key (ignored)"},
      {"SceneUnknownMode", "unknown render mode in a scene", "render mode.json" + kSmall, 2,
       "marble render: mode.json: render.mode: unknown render mode \"sparkly\"; known: paper, marble,"},
      {"SceneUnknownAntialias", "unknown antialiasing in a scene", "render antialias.json" + kSmall, 2,
       "marble render: antialias.json: render.antialias: expected \"fxaa\" or \"none\", got \"msaa\""},
      {"SceneBadUp", "up axis \"w\"", "render up.json" + kSmall, 2, "marble render: up.json: up: expected one of \"y\", \"z\", \"x\", \"-y\", \"-z\", \"-x\", got \"w\""},
      {"SceneCameraUpParallel", "camera looking along its up vector", "render parallel.json" + kSmall, 2,
       "marble render: parallel.json: camera.up: must not be parallel to the viewing direction"},
      {"SceneLightAtOrigin", "point light inside the object", "render lightorigin.json" + kSmall, 2,
       "marble render: lightorigin.json: light.position: must not be at the origin (the object is there)"},
      {"SceneLightType", "light type \"spot\"", "render spot.json" + kSmall, 2,
       "marble render: spot.json: light.type: expected \"point\" or \"directional\", got \"spot\""},
      {"SceneMeshMissing", "scene naming a missing mesh", "render meshmissing.json" + kSmall, 2,
       "marble render: meshmissing.json: mesh: nothere.obj: file not found"},
      {"SceneUnknownBuiltin", "builtin:teapot", "render teapot.json" + kSmall, 2,
       "marble render: builtin:teapot: unknown built-in mesh; known: sculpture, sphere, cube, slab, torus"},
      {"SceneMaterialType", "material value of the wrong type", "render mattype.json" + kSmall, 2,
       "marble render: mattype.json: material.turb_power: expected a number in [0, 1000], got string \"x\""},
      {"SceneMaterialRange", "material value out of range", "render matrange.json" + kSmall, 2,
       "marble render: matrange.json: material.turb_power: expected a number in [0, 1000], got -5"},
      {"SceneUnknownPreset", "scene naming an unknown preset", "render granite.json" + kSmall, 2,
       "marble render: granite.json: material.preset: granite: not a built-in preset ("},
      // Presets.
      {"PresetUnknownName", "--preset granite", "render --preset granite" + kSmall, 2, "marble render: granite: not a built-in preset ("},
      {"PresetMissingFile", "--preset of a missing file", "render --preset ./nothere.json" + kSmall, 2, "marble render: ./nothere.json: no such file"},
      {"PresetWrongType", "preset file with a wrong type", "render --preset preset_type.json" + kSmall, 2,
       "marble render: preset_type.json: turb_power: expected a number in [0, 1000], got array [1,2]"},
      {"PresetCycle", "preset that names itself as its base", "render --preset preset_cycle.json" + kSmall, 2,
       "marble render: preset_cycle.json: preset: presets nest too deeply (a cycle?)"},
      {"PresetDirectory", "--preset of a directory", "render --preset folder.obj" + kSmall, 2, "marble render: folder.obj: is a directory, not a file"},
      {"PresetBlank", "empty preset file", "render --preset blank.json" + kSmall, 2, "marble render: blank.json: empty file"},
      // Regression (found by fuzz_preset): see GltfNumberOverflow. Fails until material_io.cpp catches it.
      {"PresetNumberOverflow", "number beyond double (1e400) in a preset", "render --preset preset_overflow.json" + kSmall, 2,
       "marble render: preset_overflow.json: "},
      // Environment maps.
      {"EnvMapGood", "a good equirectangular .hdr: accepted", "render --environment-map sky.hdr" + kSmall, 0, ""},
      {"EnvMapMissing", "--environment-map of a missing file", "render --environment-map missing.hdr" + kSmall, 2,
       "marble render: missing.hdr: file not found"},
      {"EnvMapDirectory", "--environment-map of a directory", "render --environment-map folder.obj" + kSmall, 2,
       "marble render: folder.obj: is a directory, not an image file"},
      {"EnvMapGarbage", "binary garbage named .hdr", "render --environment-map garbage.hdr" + kSmall, 2,
       "marble render: garbage.hdr: not a Radiance .hdr file (it must start with the line #?RADIANCE or #?RGBE)"},
      {"EnvMapTruncated", "run-length encoded .hdr missing its last byte", "render --environment-map cut.hdr" + kSmall, 2,
       "marble render: cut.hdr: pixel data, row 31 of 32: the file ends inside the scanline (truncated)"},
      {"EnvMapNotEquirect", "square .hdr (not equirectangular)", "render --environment-map square.hdr" + kSmall, 2,
       "marble render: square.hdr: is 32 x 32 pixels; an equirectangular map is exactly twice as wide as high (e.g. 2048 x 1024)"},
      {"EnvMapHuge", ".hdr header declaring 20000 x 10000", "render --environment-map huge.hdr" + kSmall, 2,
       "marble render: huge.hdr: header line 5: image is 20,000 x 10,000 pixels; the limit is 8,192 per side"},
      {"EnvMapWithoutFile", "--environment map without a map", "render --environment map" + kSmall, 2,
       "marble render: --environment: \"map\" needs a file: add --environment-map FILE.hdr"},
      {"EnvUnknown", "--environment sky", "render --environment sky" + kSmall, 2,
       "marble render: --environment: expected \"studio\", \"none\", \"map\" or a FILE.hdr, got \"sky\""},
      {"SceneEnvMapMissing", "scene naming a missing .hdr", "render envmissing.json" + kSmall, 2,
       "marble render: envmissing.json: render.environment_map: nothere.hdr: file not found"},
      {"SceneEnvMapWithoutFile", "scene asking for \"map\" without environment_map", "render envnofile.json" + kSmall, 2,
       "marble render: envnofile.json: render.environment: \"map\" needs render.environment_map (an equirectangular .hdr file)"},
      {"SceneEnvUnknown", "scene environment \"sky\"", "render envsky.json" + kSmall, 2,
       "marble render: envsky.json: render.environment: expected \"studio\", \"none\" or \"map\", got \"sky\""},
      // Issue 18: inputs that must not hang, crash or reach what the user did not name.
      {"FifoMesh", "a FIFO given as the mesh", "render pipe.obj" + kSmall, 2,
       "marble render: pipe.obj: is a named pipe (FIFO), not a regular file; marble reads only regular files"},
      {"FifoSceneMesh", "a FIFO as a scene's mesh", "render fifomesh.json" + kSmall, 2,
       "marble render: fifomesh.json: mesh: pipe.obj: is a named pipe (FIFO), not a regular file"},
      {"FifoGltfBuffer", "a FIFO as a glTF buffer", "render fifobuffer.gltf" + kSmall, 2,
       "marble render: fifobuffer.gltf: buffer 0: cannot read 'pipe.bin': pipe.bin: is a named pipe (FIFO), not a regular file"},
      {"DeviceMesh", "/dev/zero as the mesh", "render /dev/zero" + kSmall, 2,
       "marble render: /dev/zero: is a character device, not a regular file"},
      {"SymlinkLoop", "a symbolic link loop as the mesh", "render loop1.obj" + kSmall, 2,
       "marble render: loop1.obj: too many levels of symbolic links (a symbolic link loop?)"},
      {"DanglingSymlink", "a symbolic link to nothing as the mesh", "render dangling.obj" + kSmall, 2,
       "marble render: dangling.obj: is a symbolic link to a file that does not exist"},
      {"GltfDag", "glTF whose 41 nodes each list the next one twice (2^40 paths)", "render dag.gltf" + kSmall, 2,
       "marble render: dag.gltf: node 40: is reached twice (from node 39 and from node 39); glTF requires each node to have at most one parent"},
      {"SceneDeepNesting", "scene value nested 100,000 arrays deep", "render deep.json" + kSmall, 2,
       "marble render: deep.json: line 1, column 75: JSON nested deeper than 64 levels (arrays and objects)"},
      {"GltfDeepNesting", "glTF value nested 100,000 arrays deep", "render deep.gltf" + kSmall, 2,
       "marble render: deep.gltf: line 1, column 100: JSON nested deeper than 64 levels (arrays and objects)"},
      {"SceneHugeString", "a 10 MB string where a number belongs", "render hugestring.json" + kSmall, 2,
       "marble render: hugestring.json: camera.fov_y_deg: expected a number, got string \"AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA...\""},
      {"PresetNotJson", "a file that is not JSON (a credential file) named as a preset", "render --preset credentials.json" + kSmall, 2,
       "marble render: credentials.json: invalid JSON: parse error at line 1, column 1: syntax error while parsing value - invalid literal"},
      {"GltfBufferAbsolute", "glTF buffer uri /etc/passwd", "render passwd.gltf" + kSmall, 2,
       "marble render: passwd.gltf: buffer 0: 'uri' \"/etc/passwd\" is outside the glTF's folder"},
      {"GltfBufferUpward", "glTF buffer uri ../../../../etc/passwd", "render updir.gltf" + kSmall, 2,
       "marble render: updir.gltf: buffer 0: 'uri' \"../../../../etc/passwd\" is outside the glTF's folder"},
      {"DuplicateTriangles", "100,000 copies of one triangle: one is kept, with a warning", "render copies.obj" + kSmall, 0,
       "warning: copies.obj: dropped 99,999 duplicate triangles (the same three corners as an earlier triangle, same winding)"},
      {"SparseStl", "3.9 GB sparse binary STL whose header declares no triangle", "render sparse.stl" + kSmall, 2,
       "marble render: sparse.stl: byte 80: the triangle count is 0: no triangles"},
      {"EscapeInFileName", "a file name holding a terminal escape sequence", "render esc*red.obj" + kSmall, 2,
       "marble render: esc\\x1b[31mred.obj: line 4: face has 2 vertices; a face needs at least 3"},
      {"EscapeInFileContent", "a terminal escape sequence inside an OBJ line", "render escape.obj" + kSmall, 2,
       "marble render: escape.obj: line 4: bad face vertex '\\x1b]0;pwned\\x07'"},
      {"SceneMeshError", "an error inside the mesh a scene names", "render sceneobj.json" + kSmall, 2,
       "marble render: sceneobj.json: mesh: two.obj: line 4: face has 2 vertices; a face needs at least 3"},
      {"OutputDevNull", "-o /dev/null (a device is never replaced)", "render -o /dev/null --width 16 --height 16", 2,
       "marble render: /dev/null: is a character device, not a regular file; refusing to replace it"},
      {"OutputFifo", "-o naming a FIFO", "render -o pipe.png --width 16 --height 16", 2,
       "marble render: pipe.png: is a named pipe (FIFO), not a regular file; refusing to replace it"},
      {"OutputLongName", "-o with a 250-character file name: accepted", "render -o " + std::string(246, 'n') + ".png --width 16 --height 16", 0, ""},
      // Command line.
      {"SetWithoutValue", "--set without '='", "render --set turb_power" + kSmall, 2, "marble render: --set: turb_power: expected key=value"},
      {"SetWithoutKey", "--set =3", "render --set =3" + kSmall, 2, "marble render: --set: =3: expected key=value"},
      {"SetUnknownKey", "--set of an unknown key", "render --set bogus=3" + kSmall, 2, "marble render: --set: bogus: unknown key (known: name, description,"},
      {"SetNotANumber", "--set turb_power=abc", "render --set turb_power=abc" + kSmall, 2,
       "marble render: --set: turb_power: expected a number in [0, 1000], got string \"abc\""},
      {"PresetFromDevice", "--preset /dev/zero (a device that never ends)", "render --preset /dev/zero" + kSmall, 2,
       "marble render: /dev/zero: is a character device, not a regular file; marble reads only regular files"},
      {"SetNan", "--set turb_power=nan", "render --set turb_power=nan" + kSmall, 2, "marble render: --set: turb_power: expected a finite number, got nan"},
      {"SetOutOfRange", "--set turb_power=1e9", "render --set turb_power=1e9" + kSmall, 2,
       "marble render: --set: turb_power: expected a number in [0, 1000], got 1000000000.0"},
      {"SetShortColour", "--set vein_color=1,2", "render --set vein_color=1,2" + kSmall, 2,
       "marble render: --set: vein_color: expected an array of 3 numbers in [0, 1], got array [1,2]"},
      {"UnknownMode", "--mode sparkly", "render --mode sparkly" + kSmall, 2, "marble render: --mode: unknown render mode \"sparkly\"; known: paper,"},
      {"ModeWrongCase", "--mode Paper (names are lower case)", "render --mode Paper" + kSmall, 2, "marble render: --mode: unknown render mode \"Paper\""},
      {"BadUp", "--up w", "render --up w" + kSmall, 2, "marble render: --up: expected one of y, z, x, -y, -z, -x, got \"w\""},
      {"UnknownAntialias", "--antialias msaa", "render --antialias msaa" + kSmall, 2,
       "marble render: --antialias: expected \"fxaa\" or \"none\", got \"msaa\""},
      // Look-dev flags (issue 19).
      {"LightUnknown", "--light sideways", "render --light sideways" + kSmall, 2,
       "marble render: --light: expected front, side, back, top, or AZ,EL (degrees, elevation in [-90, 90]), got \"sideways\""},
      {"LightElevation", "--light 0,120 (elevation past the zenith)", "render --light 0,120" + kSmall, 2,
       "marble render: --light: expected front, side, back, top, or AZ,EL"},
      {"LightPositionAtOrigin", "--light-position 0,0,0", "render --light-position 0,0,0" + kSmall, 2,
       "marble render: --light-position: must not be at the origin (the object is there)"},
      {"LightPositionShort", "--light-position 1,2", "render --light-position 1,2" + kSmall, 2,
       "marble render: --light-position: expected X,Y,Z (three numbers in [-10000, 10000]), got \"1,2\""},
      {"CameraElevation", "--camera 0,95", "render --camera 0,95" + kSmall, 2,
       "marble render: --camera: expected front, side, back, top, or AZ,EL[,DIST] (degrees, elevation in (-90, 90), distance in [0.2, 100]), got \"0,95\""},
      {"CameraDistance", "--camera 0,10,500", "render --camera 0,10,500" + kSmall, 2, "marble render: --camera: expected front, side,"},
      {"CameraPositionAbove", "--camera-position straight above the target", "render --camera-position 0,3,0" + kSmall, 2,
       "marble render: --camera-position: must not be straight above or below the target (the camera's up is +Y)"},
      {"CameraPositionNan", "--camera-position 1,nan,3", "render --camera-position 1,nan,3" + kSmall, 2,
       "marble render: --camera-position: expected X,Y,Z (three numbers in [-10000, 10000]), got \"1,nan,3\""},
      {"SizeZero", "--size-mm 0", "render --size-mm 0" + kSmall, 2,
       "marble render: --size-mm: expected the object's size in millimetres, in [0.002, 2000000]"},
      {"ExposureRange", "--exposure 11", "render --exposure 11" + kSmall, 2, "marble render: --exposure: expected stops in [-10, 10]"},
      {"BackgroundRange", "--background 1,2,3", "render --background 1,2,3" + kSmall, 2,
       "marble render: --background: expected R,G,B (three numbers in [0, 1]), got \"1,2,3\""},
      {"EnvironmentHdrMissing", "--environment of a missing .hdr", "render --environment nothere.hdr" + kSmall, 2,
       "marble render: nothere.hdr: file not found"},
      {"GroundNotOnOff", "--ground yes", "render --ground yes" + kSmall, 2, "marble render: --ground: expected on or off, got \"yes\""},
      {"BackdropNotOnOff", "--backdrop 1", "render --backdrop 1" + kSmall, 2, "marble render: --backdrop: expected on or off, got \"1\""},
      {"BackdropBlurRange", "--backdrop-blur 2", "render --backdrop-blur 2" + kSmall, 2, "marble render: --backdrop-blur: expected a number in [0, 1]"},
      {"SceneGroundType", "scene with \"ground\": \"yes\"", "render groundtype.json" + kSmall, 2,
       "marble render: groundtype.json: render.ground: expected true or false, got string \"yes\""},
      {"QualityUnknown", "--quality ultra", "render --quality ultra" + kSmall, 2, "marble render: --quality: expected draft or final, got \"ultra\""},
      {"TurntableZero", "--turntable 0", "render --turntable 0 -o frames --width 16 --height 16", 2,
       "marble render: --turntable: expected 1 to 3600 frames, got 0"},
      {"TurntableOfCamera", "--turntable-of camera", "render --turntable 2 --turntable-of camera -o frames --width 16 --height 16", 2,
       "marble render: --turntable-of: expected object or light, got \"camera\""},
      {"TurntableIntoPng", "--turntable with -o a .png", "render --turntable 2 -o out.png --width 16 --height 16", 2,
       "marble render: -o: out.png: --turntable writes numbered frames into a folder: give -o a folder (e.g. -o frames/)"},
      {"TurntableFps", "--fps 0", "render --turntable 2 --fps 0 -o frames --width 16 --height 16", 2,
       "marble render: --fps: expected 1 to 120 frames per second, got 0"},
      {"VideoWithoutTurntable", "--video without --turntable", "render --video out.mp4" + kSmall, 2,
       "marble render: --video: needs --turntable N (the frames to encode)"},
      {"VideoFormat", "--video out.avi", "render --turntable 2 --video out.avi -o frames --width 16 --height 16", 2,
       "marble render: --video: expected a .mp4, .webm or .webp file, got \"out.avi\""},
      {"VideoNoFfmpeg", "--video without ffmpeg installed (PATH without it)", "render --turntable 2 --video out.mp4 -o frames --width 16 --height 16", 1,
       "marble render: --video: ffmpeg is not installed (not on PATH); install the package ffmpeg", "PATH=/nonexistent"},
      {"PngWithoutScene", "a PNG that marble did not write, as the input", "render plain.png" + kSmall, 2,
       "marble render: plain.png: carries no marble scene (only PNGs written by `marble render` do)"},
      {"PngNotPng", "text named .png, as the input", "render notpng.png" + kSmall, 2, "marble render: notpng.png: not a PNG file"},
      {"SupersampleOutOfRange", "--supersample 5", "render --supersample 5" + kSmall, 2, "--supersample: Value 5 not in range 1 to 4"},
      {"SupersampleTooLarge", "--supersample 4 of a 4000-pixel-wide image", "render -o out.png --width 4000 --height 16 --supersample 4", 2,
       "marble render: --supersample: 4 times 4000x16 is 16000x64, above the limit of 8192 pixels a side; lower --supersample or the size"},
      {"ZeroWidth", "--width 0", "render -o out.png --width 0", 2, "--width: Value 0 not in range 1 to 8192"},
      {"AbsurdWidth", "--width 100000", "render -o out.png --width 100000", 2, "--width: Value 100000 not in range 1 to 8192"},
      {"NonNumericHeight", "--height abc", "render -o out.png --height abc", 2, "--height: Value abc not in range 1 to 8192"},
      {"NoOutput", "render without -o", "render", 2, "marble render: -o: an output file is required (e.g. -o out.png)"},
      {"UnknownCommand", "unknown command", "frobnicate", 2, "A subcommand is required"},
      {"ExtraArgument", "two inputs", "render a.obj b.obj" + kSmall, 2, "The following argument was not expected: b.obj"},
      // Output paths.
      {"OutputFolderMissing", "-o into a missing folder", "render -o /nonexistent/dir/out.png --width 16 --height 16", 2,
       "marble render: /nonexistent/dir/out.png: cannot write: No such file or directory"},
      {"OutputUnderAFile", "-o under a path that is a file", "render -o afile/out.png --width 16 --height 16", 2,
       "marble render: afile/out.png: cannot write: Not a directory"},
      {"OutputIsFolder", "-o naming an existing folder", "render -o folder.obj --width 16 --height 16", 2,
       "marble render: folder.obj: is a directory, not a file"},
      {"HdrFolderMissing", "--hdr into a missing folder", "render --hdr /nonexistent/x.exr" + kSmall, 2,
       "marble render: /nonexistent/x.exr: cannot write: No such file or directory"},
      {"HdrOfFloor", "--hdr with --mode floor", "render --hdr x.exr --mode floor" + kSmall, 2, "marble render: --hdr: the floor mode has no HDR image"},
      {"TextureOutputIsFile", "texture -o naming a file", "texture -o afile --size 16", 2, "afile: cannot create folder: Not a directory"},
      {"TextureTinySize", "texture --size 4", "texture -o tex --size 4", 2, "--size: Value 4 not in range 8 to 8192"},
      // bake and export (issue 17): all checked before the bake; tests/export_cli.cpp checks nothing is written.
      {"BakeNoFaces", "bake a mesh with no faces", "bake nofaces.obj -o set", 2, "marble bake: nofaces.obj: no triangles: the file has 2 vertices but no faces"},
      {"BakeOverlappingUvs", "bake --uv-from file with overlapping texture coordinates", "bake overlapuv.obj --uv-from file -o set", 2,
       "marble bake: overlapuv.obj: texcoords: the texture coordinates overlap: 100.00% of the covered texels belong to two or more triangles (--uv-from file)"},
      {"BakeTinySize", "bake --size below 16", "bake overlapuv.obj --size 8 -o set", 2, "marble bake: --size: expected a whole number in [16, 8192], got 8"},
      {"BakeHugeSize", "bake --size above 8192", "bake overlapuv.obj --size 9000 -o set", 2, "marble bake: --size: expected a whole number in [16, 8192], got 9000"},
      {"BakeSupersample", "bake --supersample out of range", "bake overlapuv.obj --supersample 9 -o set", 2, "marble bake: --supersample: expected 1 to 4, got 9"},
      {"BakeChartsDoNotFit", "bake --size too small for the unwrap's charts", "bake overlapuv.obj --uv-from unwrap --size 16 -o set", 2,
       "marble bake: overlapuv.obj: unwrap: 2 charts do not fit a 16-texel texture with 4 texels of padding (a larger --size fits them)"},
      {"BakeFolderUnderAFile", "bake -o under a path that is a file", "bake overlapuv.obj -o afile/set", 2, "marble bake: afile/set: cannot create folder: "},
      {"BakeFolderUnwritable", "bake -o where nothing can be created (/proc)", "bake overlapuv.obj --uv-from unwrap --size 64 -o /proc/marble-set", 2,
       "marble bake: /proc/marble-set: cannot create folder: No such file or directory"},
      {"ExportNotGltf", "export -o naming neither .glb nor .gltf", "export overlapuv.obj -o model.fbx", 2, "marble export: model.fbx: expected a .glb or .gltf file name"},
      {"ExportFolderMissing", "export -o into a missing folder", "export overlapuv.obj -o nowhere/model.glb", 2,
       "marble export: nowhere/model.glb: the folder nowhere does not exist"},
      {"ExportUnwritable", "export -o where nothing can be written (/proc)", "export overlapuv.obj --uv-from unwrap --size 64 -o /proc/model.glb", 2,
       "marble export: /proc/model.glb: cannot write: No such file or directory"},
      // Environment.
      {"NoEglVendor", "no EGL driver (glvnd finds no vendor)", "render" + kSmall, 1,
       "marble render: headless OpenGL: no EGL display available (is libegl-mesa0 installed?)", "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json"},
      {"GlBelow45", "OpenGL below 4.5 (Mesa capped at 3.3)", "render" + kSmall, 1, "marble render: headless OpenGL: ",
       "MESA_GL_VERSION_OVERRIDE=3.3 EGL_LOG_LEVEL=fatal"},
      {"ShaderCompileError", "a shader that fails to compile (a folder with a broken lighting.frag.glsl)", "render" + kSmall, 1,
       "marble render: brokenshaders/lighting.frag.glsl:3: error: `undeclared_thing' undeclared", "MARBLE_SHADER_DIR=brokenshaders"},
      {"ShaderIncludeMissing", "a shader that includes a file that does not exist", "render" + kSmall, 1,
       "marble render: brokeninclude/post.frag.glsl:2: error: #include \"nothere.glsl\": no such shader", "MARBLE_SHADER_DIR=brokeninclude"},
      {"ShaderDirMissing", "MARBLE_SHADER_DIR naming no folder", "render" + kSmall, 2,
       "marble render: MARBLE_SHADER_DIR: 'nothere' is not a folder", "MARBLE_SHADER_DIR=nothere"},
      {"ViewerBadTurntable", "viewer turntable not off, object or light", "view --turntable spin --frames 1", 2,
       "marble view: --turntable: expected off, object or light, got \"spin\""},
      {"ViewerTurntableSpeed", "viewer turntable speed out of range", "view --turntable object --turntable-speed 1e9 --frames 1", 2,
       "marble view: --turntable-speed: expected -3600 to 3600 degrees per second, got 1e+09"},
      {"ViewerNoDisplay", "viewer without DISPLAY", "view --frames 1", 1,
       "marble view: no display (DISPLAY is not set); use `marble render [INPUT] -o out.png` to render without one", "env -u DISPLAY -u WAYLAND_DISPLAY"},
      {"ViewerDeadDisplay", "viewer with DISPLAY naming no X server", "view --frames 1", 1, "marble view: cannot open a window: X11: Failed to open display :8765",
       "DISPLAY=:8765"},
  };
  return r;
}

struct Captured {
  int exitCode = -1;
  std::string stderrText;
};

// Like cli_support.h's runMarble, but in `dir` and with stderr alone (stdout is discarded), so
// the one-line rule can be checked on what a user sees as errors.
Captured runIn(const fs::path& dir, const Row& row) {
  const std::string cmd = "cd '" + dir.string() + "' && " + row.env + " " + MARBLE_BINARY + " " + row.args + " 2>&1 >/dev/null";
  Captured c;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return c;
  std::array<char, 4096> buf{};
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) c.stderrText.append(buf.data(), n);
  const int status = pclose(pipe);
  c.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return c;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start < text.size()) {
    const size_t nl = text.find('\n', start);
    out.push_back(text.substr(start, nl == std::string::npos ? std::string::npos : nl - start));
    if (nl == std::string::npos) break;
    start = nl + 1;
  }
  return out;
}

std::string markdownCell(std::string s) {
  for (size_t i = 0; (i = s.find('|', i)) != std::string::npos; i += 2) s.replace(i, 1, "\\|");
  return s;
}

// A code span around s; GLSL compilers quote names as `name', so a span holding a backtick is
// opened and closed with two (CommonMark, "code spans").
std::string code(const std::string& s) {
  return s.find('`') == std::string::npos ? "`" + s + "`" : "`` " + s + " ``";
}

class BadInputs : public ::testing::TestWithParam<Row> {
protected:
  static void SetUpTestSuite() {
    scratch_ = std::make_unique<marble::test::TempDir>("bad-inputs");
    dir_ = scratch_->path();
    writeInputs(dir_);
  }
  static void TearDownTestSuite() { scratch_.reset(); }
  static inline std::unique_ptr<marble::test::TempDir> scratch_;
  static inline fs::path dir_;
};

TEST_P(BadInputs, OneLineAndTheRightExitCode) {
  const Row& row = GetParam();
  const Captured c = runIn(dir_, row);
  const auto got = lines(c.stderrText);
  EXPECT_EQ(c.exitCode, row.exitCode) << c.stderrText;
  if (row.message.empty()) {
    EXPECT_TRUE(got.empty()) << "expected no message, got:\n" << c.stderrText;
  } else {
    ASSERT_FALSE(got.empty()) << "no message on stderr";
    EXPECT_NE(got[0].find(row.message), std::string::npos) << "expected: " << row.message << "\n     got: " << got[0];
    // CLI11's usage errors end with "Run with --help or --help-all for more information." (reported).
    EXPECT_EQ(got.size(), row.usageError ? 2u : 1u) << c.stderrText;
  }
  if (const char* table = std::getenv("MARBLE_BAD_INPUTS_TABLE")) {
    std::ofstream out(table, std::ios::app);
    out << "| " << markdownCell(row.what) << " | `marble " << markdownCell(row.args) << "`"
        << (*row.env ? std::string(" with `") + row.env + "`" : "") << " | " << c.exitCode << " | "
        << (got.empty() ? "(nothing; stdout says `wrote out.png ...`)" : code(markdownCell(got[0]))) << " |\n";
  }
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInputs, ::testing::ValuesIn(rows()),
                         [](const ::testing::TestParamInfo<Row>& info) { return std::string(info.param.name); });

}  // namespace
