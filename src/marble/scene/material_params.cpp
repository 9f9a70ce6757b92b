#include "marble/scene/material_params.h"

#include <sstream>

#include "marble/scene/scene.h"

namespace marble {
namespace {

constexpr ModeSet kShadingModes = modeBit(RenderMode::Paper) | modeBit(RenderMode::Marble) |
                                  modeBit(RenderMode::Phong) | modeBit(RenderMode::OrenNayar) |
                                  modeBit(RenderMode::Subsurface) | modeBit(RenderMode::Reflectance) |
                                  modeBit(RenderMode::Albedo);  // modeShowsAlbedo
constexpr ModeSet kMarble = modeBit(RenderMode::Marble);
constexpr uint32_t kPattern = kAlbedoPassBit;

constexpr EnumChoice kBasis[] = {{static_cast<int>(NoiseBasis::Value), "value", "value (paper)"},
                                 {static_cast<int>(NoiseBasis::Perlin), "perlin", "Perlin gradient"}};
constexpr EnumChoice kMapping[] = {{static_cast<int>(PatternMapping::Planar), "planar", "planar x/z (paper)"},
                                   {static_cast<int>(PatternMapping::Triplanar), "triplanar", "triplanar"},
                                   {static_cast<int>(PatternMapping::Solid), "solid", "solid 3D"}};
constexpr EnumChoice kOrder[] = {
    {static_cast<int>(ShadingOrder::SubsurfaceFirst), "sss-first", "subsurface first (paper)"},
    {static_cast<int>(ShadingOrder::ReflectanceFirst), "schlick-first", "reflectance first"}};
constexpr EnumChoice kBlend[] = {{static_cast<int>(SchlickBlend::Opacity), "opacity", "opacity (paper's text)"},
                                 {static_cast<int>(SchlickBlend::Program), "program", "subtract (paper's program)"}};
constexpr EnumChoice kVeinModel[] = {{static_cast<int>(VeinModel::Paper), "paper", "paper (|sin|)"},
                                     {static_cast<int>(VeinModel::Network), "network", "crack network"},
                                     {static_cast<int>(VeinModel::Breccia), "breccia", "breccia"}};
constexpr EnumChoice kScatteringForm[] = {
    {static_cast<int>(ScatteringForm::Coefficients), "coefficients", "coefficients (sigma_a, sigma_s')"},
    {static_cast<int>(ScatteringForm::Radius), "radius", "radius (Blender's Principled BSDF)"}};
constexpr EnumChoice kCos[] = {{static_cast<int>(SchlickCosine::HdotV), "hv", "H.V (standard)"},
                               {static_cast<int>(SchlickCosine::HdotN), "hn", "H.N (paper)"}};

// When a parameter is used, given the others (ParamDesc::active).
bool paperVeins(const Material& m) { return m.vein_model == VeinModel::Paper; }
bool veinNetwork(const Material& m) { return m.vein_model != VeinModel::Paper; }
bool breccia(const Material& m) { return m.vein_model == VeinModel::Breccia; }
bool coefficientForm(const Material& m) { return m.scattering == ScatteringForm::Coefficients; }
bool radiusForm(const Material& m) { return m.scattering == ScatteringForm::Radius; }
constexpr const char* kWithVeinModel = "with a vein model (vein_model network or breccia) it is not used";
constexpr const char* kWithPaperVeins = "used only with vein_model network or breccia";
ParamValue veinDirectionValue(const Material& m) { return veinDirection(m); }

#define MARBLE_FIELD(member) .get = &getField<&member>, .set = &setField<&member>

const ParamDesc kParams[] = {
    // --- identity ---
    {.key = "name", .group = ParamGroup::Identity, .type = ParamType::Text, .lo = 0, .hi = 0, .atMost = nullptr,
     .unit = "", .label = "name", .tooltip = "The preset's name.", .doc = "preset name (shown by `marble presets`)",
     .modes = 0, .passes = 0, .uniform = nullptr, .choices = {}, .slider = {}, MARBLE_FIELD(Material::name)},
    {.key = "description", .group = ParamGroup::Identity, .type = ParamType::Text, .lo = 0, .hi = 0, .atMost = nullptr,
     .unit = "", .label = "description", .tooltip = "One line about the look.", .doc = "one line about the look",
     .modes = 0, .passes = 0, .uniform = nullptr, .choices = {}, .slider = {}, MARBLE_FIELD(Material::description)},

    // --- pattern (paper §3.1) ---
    {.key = "seed", .group = ParamGroup::Pattern, .type = ParamType::UInt, .lo = 0, .hi = 4294967295.0,
     .atMost = nullptr, .unit = "", .label = "seed",
     .tooltip = "Seed of the white-noise lattice: another block of the same stone.",
     .doc = "white-noise lattice seed (integer hash of the cell; the same bits on CPU and GPU)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_seed", .choices = {},
     .slider = {0.0f, 1.0e6f, false, "%.0f"}, MARBLE_FIELD(PatternParams::seed)},
    {.key = "resolution", .group = ParamGroup::Pattern, .type = ParamType::Int, .lo = 8, .hi = 4096, .atMost = nullptr,
     .unit = "texels", .label = "resolution",
     .tooltip = "Texels across the pattern: the density of the white-noise lattice. More gives finer detail.",
     .doc = "W: texels across the texture = value-noise cells per `2·pattern_scale` object units at the finest "
            "octave; lattice period",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_resolution", .choices = {},
     .slider = {16.0f, 1024.0f, true}, MARBLE_FIELD(PatternParams::resolution)},
    {.key = "basis", .group = ParamGroup::Pattern, .type = ParamType::Choice, .lo = 0, .hi = 0, .atMost = nullptr,
     .unit = "", .label = "noise",
     .tooltip = "Smooth-noise basis under the turbulence. Value noise is the paper's; Perlin has fewer grid artefacts.",
     .doc = "smooth noise: `\"value\"` (the paper's: the lattice interpolated bilinearly / trilinearly) or "
            "`\"perlin\"` (Perlin's improved gradient noise, 2002, mapped to [0, 1])",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_basis", .choices = kBasis, .slider = {},
     MARBLE_FIELD(PatternParams::basis)},
    {.key = "mapping", .group = ParamGroup::Pattern, .type = ParamType::Choice, .lo = 0, .hi = 0, .atMost = nullptr,
     .unit = "", .label = "mapping",
     .tooltip = "How the pattern meets the surface. Planar: the paper's 2D texture on x/z, stretched along y.\n"
                "Triplanar: three planar projections blended by the normal.\n"
                "Solid: a block of stone cut into the shape (veins run through edges).",
     .doc = "`\"planar\"`: the paper's — s, t from object x, z, constant along y (the pattern stretches along y), "
            "mirrored beyond the texture (GL_MIRRORED_REPEAT: mirror planes at x = 0, ±2·pattern_scale, …; same for "
            "z), kept for comparison; `\"triplanar\"`: three planar projections blended by the normal⁴; `\"solid\"`: "
            "the pattern in 3D at the object-space position — continuous everywhere, like a block cut to shape",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_mapping", .choices = kMapping, .slider = {},
     MARBLE_FIELD(PatternParams::mapping)},
    {.key = "x_period", .group = ParamGroup::Pattern, .type = ParamType::Float, .lo = -1000, .hi = 1000,
     .atMost = nullptr, .unit = "", .label = "x period",
     .tooltip = "Vein repetitions along x. With the y period it sets the angle and spacing of the veins.\n"
                "Both 0: turbulence alone.",
     .doc = "vein repetitions along x across the texture (with `y_period`: angle and spacing of the veins)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_x_period", .choices = {},
     .slider = {0.0f, 20.0f, false}, MARBLE_FIELD(PatternParams::x_period),
     .active = &paperVeins, .inactive = kWithVeinModel},
    {.key = "y_period", .group = ParamGroup::Pattern, .type = ParamType::Float, .lo = -1000, .hi = 1000,
     .atMost = nullptr, .unit = "", .label = "y period", .tooltip = "Vein repetitions along y (the texture's t).",
     .doc = "repetitions along the texture's t (object z in planar, object y in solid)", .modes = kShadingModes,
     .passes = kPattern, .uniform = "u_pat_y_period", .choices = {}, .slider = {0.0f, 20.0f, false},
     MARBLE_FIELD(PatternParams::y_period),
     .active = &paperVeins, .inactive = kWithVeinModel},
    {.key = "z_period", .group = ParamGroup::Pattern, .type = ParamType::Float, .lo = -1000, .hi = 1000,
     .atMost = nullptr, .unit = "", .label = "z period", .tooltip = "Vein repetitions along z (solid mapping only).",
     .doc = "repetitions along object z (solid mapping only)", .modes = kShadingModes, .passes = kPattern,
     .uniform = "u_pat_z_period", .choices = {}, .slider = {0.0f, 20.0f, false}, MARBLE_FIELD(PatternParams::z_period),
     .active = &paperVeins, .inactive = kWithVeinModel},
    {.key = "turb_power", .group = ParamGroup::Pattern, .type = ParamType::Float, .lo = 0, .hi = 1000,
     .atMost = nullptr, .unit = "", .label = "turbulence",
     .tooltip = "How far the turbulence bends the veins. 0 gives straight sine stripes, high values chaotic folds.",
     .doc = "how far turbulence bends the veins; 0 gives a plain sine; with all periods 0 the pattern is "
            "turbulence alone",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_turb_power", .choices = {},
     .slider = {0.0f, 20.0f, false}, MARBLE_FIELD(PatternParams::turb_power),
     .active = &paperVeins, .inactive = kWithVeinModel},
    {.key = "turb_size", .group = ParamGroup::Pattern, .type = ParamType::Float, .lo = 1, .hi = 4096,
     .atMost = "resolution", .unit = "texels", .label = "turbulence size",
     .tooltip = "Size of the largest turbulence octave, in texels (at most the resolution); each octave halves it.\n"
                "Large: broad swirls. Small: fine grain.",
     .doc = "first (largest) octave size in texels; halves each octave down to 1, so log2(turb_size)+1 octaves",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_turb_size", .choices = {},
     .slider = {1.0f, 1024.0f, true}, MARBLE_FIELD(PatternParams::turb_size)},
    {.key = "pattern_scale", .group = ParamGroup::Pattern, .type = ParamType::Float, .lo = 0.001, .hi = 1000,
     .atMost = nullptr, .unit = "object units", .label = "pattern scale",
     .tooltip = "Size of the pattern on the object: larger spreads the veins out.",
     .doc = "object units per half texture width (smaller: finer, repeated pattern)", .modes = kShadingModes,
     .passes = kPattern, .uniform = "u_pat_scale", .choices = {}, .slider = {0.1f, 8.0f, true},
     MARBLE_FIELD(PatternParams::pattern_scale)},

    // --- colour ---
    {.key = "base_color", .group = ParamGroup::BaseColour, .type = ParamType::Colour, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "linear RGB", .label = "base", .tooltip = "Albedo of the stone between veins (linear RGB).",
     .doc = "the stone between veins; also the `floor` mode's flat colour and, in `marble`, the albedo of the light bounced inside the object",
     .modes = kShadingModes | modeBit(RenderMode::Floor), .passes = kPattern | kFloorPassBit | kBouncePassBit,
     .uniform = "u_pat_base_color", .choices = {}, .slider = {}, MARBLE_FIELD(BaseColourParams::base_color)},
    {.key = "vein_color", .group = ParamGroup::Colour, .type = ParamType::Colour, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "linear RGB", .label = "vein", .tooltip = "Albedo at the heart of a vein (linear RGB).",
     .doc = "the heart of the veins", .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_color",
     .choices = {}, .slider = {}, MARBLE_FIELD(ColourParams::vein_color)},
    {.key = "vein2_color", .group = ParamGroup::Colour, .type = ParamType::Colour, .lo = 0, .hi = 1,
     .atMost = nullptr, .unit = "linear RGB", .label = "vein 2",
     .tooltip = "Secondary vein colour, between base and vein on the ramp.",
     .doc = "the middle of the ramp: vein edges / secondary veins; a colour near base_color softens veins, one near "
            "vein_color widens them, a dark one on a dark base gives thin bright veins (Nero Marquina)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein2_color", .choices = {}, .slider = {},
     MARBLE_FIELD(ColourParams::vein2_color)},
    {.key = "vein_sharpness", .group = ParamGroup::Colour, .type = ParamType::Float, .lo = 0.05, .hi = 20,
     .atMost = nullptr, .unit = "", .label = "vein sharpness",
     .tooltip = "Exponent on the sine pattern: higher gives thinner, crisper veins; 1 is the paper.",
     .doc = "exponent 1/s on the sine: 1 = the paper, > 1 thinner, crisper veins, < 1 wider", .modes = kShadingModes,
     .passes = kPattern, .uniform = "u_pat_vein_sharpness", .choices = {}, .slider = {0.1f, 8.0f, true},
     MARBLE_FIELD(ColourParams::vein_sharpness),
     .active = &paperVeins, .inactive = kWithVeinModel},
    {.key = "vein2_amount", .group = ParamGroup::Colour, .type = ParamType::Float, .lo = 0, .hi = 1,
     .atMost = nullptr, .unit = "", .label = "vein 2 amount",
     .tooltip = "How much of the secondary colour the ramp uses: 0 is the paper's two-colour ramp.",
     .doc = "0 = two-colour ramp (the paper), 1 = full three-stop ramp", .modes = kShadingModes, .passes = kPattern,
     .uniform = "u_pat_vein2_amount", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(ColourParams::vein2_amount),
     .active = &paperVeins, .inactive = kWithVeinModel},

    // --- vein model (issue 16) ---
    {.key = "vein_model", .group = ParamGroup::VeinModel, .type = ParamType::Choice, .lo = 0, .hi = 0, .atMost = nullptr,
     .unit = "", .label = "vein model",
     .tooltip = "paper: the paper's veins, contour lines of |sin(ramp + turbulence)|.\n"
                "crack network: veins are mineral-filled fractures that fork, rejoin, swell and fade (Carrara, Calacatta).\n"
                "breccia: angular fragments of stone cemented by a matrix, cut by crack veins (Rosso Levanto, Emperador).\n"
                "The network models are solid (object space) whatever the mapping; the turbulence above warps them.",
     .doc = "`\"paper\"`: contour lines of |sin(ramp + turbulence)| (the paper); `\"network\"`: crack networks (Carrara, "
            "Calacatta, Statuario, Nero Marquina); `\"breccia\"`: angular fragments in a matrix, cut by cracks (Emperador, "
            "Verde Alpi, Rosso Levanto)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_model", .choices = kVeinModel, .slider = {},
     MARBLE_FIELD(VeinModelParams::vein_model), .active = nullptr, .inactive = nullptr, .hideInactive = false},
    {.key = "vein_spacing", .group = ParamGroup::VeinModel, .type = ParamType::Vec3, .lo = 0.005, .hi = 100, .atMost = nullptr,
     .unit = "object units", .label = "spacing",
     .tooltip = "Mean distance between cracks of each family (dominant, secondary, hairline), object units (the object is 2 across).\n"
                "Breccia: the first is the fragments' size.",
     .doc = "mean distance between the cracks of each family; breccia: the first is the fragments' size",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_spacing", .choices = {}, .slider = {0.01f, 4.0f, true},
     MARBLE_FIELD(VeinModelParams::vein_spacing), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "vein_width", .group = ParamGroup::VeinModel, .type = ParamType::Vec3, .lo = 0, .hi = 10, .atMost = nullptr,
     .unit = "object units", .label = "width",
     .tooltip = "Full width of each family's veins, object units: how thick the mineral filling is.\n"
                "Breccia: the first is the matrix between fragments; the others also between the smaller fragments of broken ones.",
     .doc = "full thickness of each family's mineral filling; breccia: the first is the matrix, the others also the matrix "
            "between the smaller fragments of broken ones (`fragment_split`)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_width", .choices = {}, .slider = {1.0e-4f, 0.5f, true, "%.4g"},
     MARBLE_FIELD(VeinModelParams::vein_width), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "vein_density", .group = ParamGroup::VeinModel, .type = ParamType::Vec3, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "density",
     .tooltip = "Fraction of each family's cracks that are filled: 1 a closed network, low values isolated veins that end.",
     .doc = "fraction of each family's cracks that are filled: 1 a closed network, low values isolated veins that end",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_density", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::vein_density), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "vein_normal", .group = ParamGroup::VeinModel, .type = ParamType::Vec3, .lo = -1, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "vein normal",
     .tooltip = "Normal (object space) of the planes the dominant veins lie in: the stone's bedding.\n"
                "A cut across it shows roughly parallel veins; a cut along it broad clouds (a 'fleuri' cut).",
     .doc = "normal of the planes the dominant veins lie in (the bedding); normalized on use, not all 0. A cut across it "
            "shows near-parallel veins, a cut along it broad clouds (a \"fleuri\" cut)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_normal", .choices = {}, .slider = {-1.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::vein_normal), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true, .uniformValue = &veinDirectionValue},
    {.key = "vein_stretch", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 1, .hi = 20, .atMost = nullptr,
     .unit = "", .label = "stretch",
     .tooltip = "How much thinner the dominant cells are across the vein normal: 1 veins in every direction, high parallel veins "
                "(Statuario, Calacatta).\nThe secondary family gets its square root, hairlines none.",
     .doc = "how many times thinner the dominant cells are across `vein_normal` (secondary: its square root; hairlines: 1)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_stretch", .choices = {}, .slider = {1.0f, 20.0f, true},
     MARBLE_FIELD(VeinModelParams::vein_stretch), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "vein_warp", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 0, .hi = 10, .atMost = nullptr,
     .unit = "object units", .label = "warp",
     .tooltip = "How far the turbulence bends the cracks, object units: 0 straight-faced cells, high meandering, folded veins.",
     .doc = "how far the turbulence bends the cracks",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_warp", .choices = {}, .slider = {0.0f, 2.0f, false},
     MARBLE_FIELD(VeinModelParams::vein_warp), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "vein_pinch", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "pinch",
     .tooltip = "How much a vein's width swells and pinches along it: 0 constant width, 1 veins that thin out and vanish.",
     .doc = "how much a vein's width varies along it: width × (1 ± `vein_pinch`); at 1 veins thin out to nothing",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_pinch", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::vein_pinch), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "vein_softness", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "softness",
     .tooltip = "Edge blur relative to the width: 0 crisp fractures, 1 veins that bleed into the ground.",
     .doc = "edge blur relative to the width: 0 crisp fractures, 1 veins that bleed into the ground",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein_softness", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::vein_softness), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "vein3_color", .group = ParamGroup::VeinModel, .type = ParamType::Colour, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "linear RGB", .label = "vein 3",
     .tooltip = "Albedo of the hairline veins (linear RGB).",
     .doc = "hairline veins (dominant: `vein_color`, secondary: `vein2_color`)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_vein3_color", .choices = {}, .slider = {},
     MARBLE_FIELD(VeinModelParams::vein3_color), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "cloud_color", .group = ParamGroup::VeinModel, .type = ParamType::Colour, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "linear RGB", .label = "clouds",
     .tooltip = "The ground's clouds (Carrara's nuvolato) and the breccia fragments' tints (linear RGB).",
     .doc = "the ground's clouds (Carrara's *nuvolato*) and the breccia fragments' tints",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_cloud_color", .choices = {}, .slider = {},
     MARBLE_FIELD(VeinModelParams::cloud_color), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "cloud_amount", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "cloud amount",
     .tooltip = "How strongly the ground clouds toward the cloud colour: 0 a plain ground.",
     .doc = "how strongly the ground clouds toward `cloud_color`",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_cloud_amount", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::cloud_amount), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "grain_amount", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "grain",
     .tooltip = "Contrast of the fine calcite grain (crystals about 1.5 texels across).",
     .doc = "contrast of the calcite grain (one value-noise octave at 1.5 texels, multiplicative)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_grain_amount", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::grain_amount), .active = &veinNetwork, .inactive = kWithPaperVeins, .hideInactive = true},
    {.key = "fragment_tint", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "fragment tint",
     .tooltip = "How much the fragments differ in colour, from the base toward the cloud colour.",
     .doc = "breccia: how far each fragment's colour goes from `base_color` toward `cloud_color` (at random per fragment)",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_fragment_tint", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::fragment_tint), .active = &breccia, .inactive = "used only with vein_model breccia", .hideInactive = true},
    {.key = "fragment_split", .group = ParamGroup::VeinModel, .type = ParamType::Float, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "fragment split",
     .tooltip = "Chance that a fragment is broken again into fragments of the next finer spacing (secondary, then hairline).\n"
                "0: fragments of one size (crackle glaze); 0.3-0.6: clasts, smaller fragments and grit, as in real breccias.",
     .doc = "breccia: probability that a fragment is broken again into the cells of the next finer family (a fragmentation "
            "cascade, Turcotte 1986): 0 fragments of one size; sizes then follow N(>r) ~ r^-D, D = 3 + ln p / ln r for a "
            "spacing ratio r (0.5 and 3: D = 2.4), over the range the three spacings span",
     .modes = kShadingModes, .passes = kPattern, .uniform = "u_pat_fragment_split", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(VeinModelParams::fragment_split), .active = &breccia, .inactive = "used only with vein_model breccia", .hideInactive = true},

    // --- the paper's models (§3.2, §3.3, §4) ---
    {.key = "sigma_t", .group = ParamGroup::PaperModel, .type = ParamType::Vec3, .lo = 0, .hi = 1000,
     .atMost = nullptr, .unit = "1/scene unit", .label = "sigma_t rgb",
     .tooltip = "Extinction per scene unit, per channel: light through thickness d keeps exp(-sigma_t * d).\n"
                "Low: translucent, glowing edges. High: opaque. Red travels further in marble than blue.\n"
                "(The object is 2 units across.)",
     .doc = "extinction per scene unit, per channel: subsurface term `exp(−thickness·sigma_t)` (paper §3.2, GPU "
            "Gems 1 ch. 16)",
     .modes = modeBit(RenderMode::Paper) | modeBit(RenderMode::Subsurface), .passes = kLightingPassBit,
     .uniform = "u_sigma_t", .choices = {}, .slider = {0.0f, 10.0f, false}, MARBLE_FIELD(PaperModelParams::sigma_t)},
    {.key = "k_sss", .group = ParamGroup::PaperModel, .type = ParamType::Float, .lo = 0, .hi = 1, .atMost = nullptr,
     .unit = "", .label = "k_sss", .tooltip = "Strength of the subsurface term: 0 = off, 1 = full.",
     .doc = "strength of the subsurface term", .modes = modeBit(RenderMode::Paper) | modeBit(RenderMode::Subsurface),
     .passes = kLightingPassBit, .uniform = "u_k_sss", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(PaperModelParams::k_sss)},
    {.key = "k_schlick", .group = ParamGroup::PaperModel, .type = ParamType::Float, .lo = 0, .hi = 1,
     .atMost = nullptr, .unit = "", .label = "k_schlick",
     .tooltip = "Weight of the Fresnel-Schlick term over the colour (paper 3.3): 0 shows the colour alone, 1 the "
                "Schlick term alone. Grazing angles reflect most.",
     .doc = "weight of the Schlick reflectance over the colour (paper §3.3)", .modes = modeBit(RenderMode::Paper),
     .passes = kLightingPassBit, .uniform = "u_k_schlick", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(PaperModelParams::k_schlick)},
    {.key = "metalness", .group = ParamGroup::PaperModel, .type = ParamType::Float, .lo = 0, .hi = 1,
     .atMost = nullptr, .unit = "", .label = "metalness",
     .tooltip = "F0 = mix(0.04, albedo, metalness). Calcite is a dielectric: keep 0.",
     .doc = "F0 = mix(0.04, diffuse, metalness)", .modes = modeBit(RenderMode::Paper) | modeBit(RenderMode::Reflectance),
     .passes = kLightingPassBit, .uniform = "u_metalness", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(PaperModelParams::metalness)},
    {.key = "order", .group = ParamGroup::PaperModel, .type = ParamType::Choice, .lo = 0, .hi = 0, .atMost = nullptr,
     .unit = "", .label = "order",
     .tooltip = "Which term is applied first (paper section 4). Changes how the reflectance tints the glow.",
     .doc = "`\"sss-first\"`: subsurface, then reflectance on its result (the paper's default); `\"schlick-first\"`: "
            "the reverse",
     .modes = modeBit(RenderMode::Paper), .passes = kLightingPassBit, .uniform = "u_reflectance_first",
     .choices = kOrder, .slider = {}, MARBLE_FIELD(PaperModelParams::order)},
    {.key = "schlick_cos", .group = ParamGroup::PaperModel, .type = ParamType::Choice, .lo = 0, .hi = 0,
     .atMost = nullptr, .unit = "", .label = "Schlick cos",
     .tooltip = "The angle in (1 - cos)^5. The standard form uses H.V; the paper wrote H.N.",
     .doc = "the cosine in Schlick's formula: `\"hv\"` (H·V, the textbook one) or `\"hn\"` (H·N, as the paper "
            "writes it)",
     .modes = modeBit(RenderMode::Paper) | modeBit(RenderMode::Reflectance), .passes = kLightingPassBit,
     .uniform = "u_schlick_hn", .choices = kCos, .slider = {}, MARBLE_FIELD(PaperModelParams::schlick_cos)},
    {.key = "schlick_blend", .group = ParamGroup::PaperModel, .type = ParamType::Choice, .lo = 0, .hi = 0,
     .atMost = nullptr, .unit = "", .label = "Schlick blend",
     .tooltip = "How the Schlick term F meets the colour C. Opacity (the paper's text): mix(C, F, k_schlick).\n"
                "Subtract (the paper's own program): C - k_schlick * (1 - F), which darkens the stone except at\n"
                "grazing angles.",
     .doc = "`\"opacity\"`: k_schlick is the Schlick term's opacity over the colour C, `mix(C, F, k)` (the paper's "
            "§3.3 text); `\"program\"`: `C − k·(1 − F)`, what the paper's own program computes "
            "(judgyknowitall/marble-renderable, `lightPass.fs.glsl`; preset `paper-program`)",
     .modes = modeBit(RenderMode::Paper), .passes = kLightingPassBit, .uniform = "u_schlick_program",
     .choices = kBlend, .slider = {}, MARBLE_FIELD(PaperModelParams::schlick_blend)},

    // --- comparison models ---
    {.key = "shininess", .group = ParamGroup::Comparison, .type = ParamType::Float, .lo = 0, .hi = 10000,
     .atMost = nullptr, .unit = "", .label = "Phong shininess",
     .tooltip = "Specular exponent of the 'phong' render mode: higher is a smaller, sharper highlight.",
     .doc = "Phong exponent", .modes = modeBit(RenderMode::Phong), .passes = kLightingPassBit,
     .uniform = "u_shininess", .choices = {}, .slider = {1.0f, 512.0f, true}, MARBLE_FIELD(ComparisonParams::shininess)},
    {.key = "oren_nayar_sigma", .group = ParamGroup::Comparison, .type = ParamType::Float, .lo = 0, .hi = 1.5708,
     .atMost = nullptr, .unit = "radians", .label = "Oren-Nayar sigma",
     .tooltip = "Surface roughness (radians) of the 'oren-nayar' render mode: 0 is Lambert, higher is flatter.",
     .doc = "Oren-Nayar roughness", .modes = modeBit(RenderMode::OrenNayar), .passes = kLightingPassBit,
     .uniform = "u_oren_nayar_sigma", .choices = {}, .slider = {0.0f, 1.5707f, false},
     MARBLE_FIELD(ComparisonParams::oren_nayar_sigma)},

    // --- physically based marble: scattering ---
    // Measured coefficients span decades (marble's sigma_a is 0.002-0.007 /mm, a dark stone's 0.6):
    // logarithmic sliders, with four significant digits so 0.0021 does not read 0.00.
    {.key = "subsurface_radius_mm", .group = ParamGroup::Scattering, .type = ParamType::Vec3, .lo = 1e-3, .hi = 1e4,
     .atMost = nullptr, .unit = "mm", .label = "radius mm",
     .tooltip = "Mean free path per channel in millimetres, exactly Blender's Subsurface Radius (times Subsurface)\n"
                "for RANDOM_WALK. Longer: more translucent. The base colour is the albedo.",
     .doc = "radius form: Blender's Principled BSDF *Subsurface Radius* (× *Subsurface*) for the RANDOM_WALK method, "
            "mean free path per channel; `base_color` is then the subsurface albedo (Blender's *Subsurface Color*). "
            "The default is Jensen's marble's extinction at albedo 0.83, 0.79, 0.75",
     .modes = kMarble, .passes = kLightingPassBit | kBlurPassBit, .uniform = nullptr, .choices = {},
     .slider = {0.01f, 1000.0f, true, "%.4g"}, MARBLE_FIELD(ScatteringParams::subsurface_radius_mm),
     .active = &radiusForm, .inactive = "used only in the radius form (scattering \"radius\")"},
    {.key = "sigma_a_mm", .group = ParamGroup::Scattering, .type = ParamType::Vec3, .lo = 0, .hi = 1000,
     .atMost = nullptr, .unit = "1/mm", .label = "sigma_a 1/mm",
     .tooltip = "Measured absorption per millimetre, per channel: light lost inside the stone. Higher: darker, more "
                "coloured glow.",
     .doc = "absorption coefficient, RGB (Jensen et al. 2001: marble 0.0021, 0.0041, 0.0071)", .modes = kMarble,
     .passes = kLightingPassBit | kBlurPassBit, .uniform = nullptr, .choices = {},
     .slider = {1.0e-4f, 2.0f, true, "%.4g"}, MARBLE_FIELD(ScatteringParams::sigma_a_mm),
     .active = &coefficientForm, .inactive = "in the radius form (scattering \"radius\") it is derived from base_color, subsurface_radius_mm and ior"},
    {.key = "sigma_s_mm", .group = ParamGroup::Scattering, .type = ParamType::Vec3, .lo = 0, .hi = 10000,
     .atMost = nullptr, .unit = "1/mm", .label = "sigma_s' 1/mm",
     .tooltip = "Reduced scattering per millimetre, per channel: how often light turns inside. Higher: milkier, "
                "shorter glow.",
     .doc = "reduced scattering coefficient, RGB (Jensen et al. 2001: marble 2.19, 2.62, 3.00)", .modes = kMarble,
     .passes = kLightingPassBit | kBlurPassBit, .uniform = nullptr, .choices = {},
     .slider = {0.01f, 10.0f, true, "%.4g"}, MARBLE_FIELD(ScatteringParams::sigma_s_mm),
     .active = &coefficientForm, .inactive = "in the radius form (scattering \"radius\") it is derived from base_color, subsurface_radius_mm and ior"},
    {.key = "ior", .group = ParamGroup::Scattering, .type = ParamType::Float, .lo = 1.0, .hi = 3.0, .atMost = nullptr,
     .unit = "", .label = "ior",
     .tooltip = "Index of refraction: sets F0 = ((n-1)/(n+1))^2, the highlight's strength, and in the radius form the\n"
                "stone's coefficients (Cycles' conversion); light entering the stone follows the Principled coupling, as in Blender.\n"
                "Calcite is 1.49-1.66 (F0 about 0.04-0.06).",
     .doc = "index of refraction; F0 = ((n−1)/(n+1))²; calcite 1.486–1.658", .modes = kMarble,
     .passes = kLightingPassBit | kPostPassBit | kBouncePassBit, .uniform = "u_ior", .choices = {}, .slider = {1.0f, 3.0f, false},
     MARBLE_FIELD(ScatteringParams::ior)},
    {.key = "translucency", .group = ParamGroup::Scattering, .type = ParamType::Float, .lo = 0.0, .hi = 10.0,
     .atMost = nullptr, .unit = "", .label = "translucency",
     .tooltip = "Scales light transmitted through thin parts: 1 is physical, 0 opaque, above 1 exaggerated.",
     .doc = "scale on the light transmitted through thin parts (1 = as measured)", .modes = kMarble,
     .passes = kLightingPassBit, .uniform = "u_translucency", .choices = {}, .slider = {0.0f, 2.0f, false},
     MARBLE_FIELD(ScatteringParams::translucency)},
    {.key = "scattering", .group = ParamGroup::Scattering, .type = ParamType::Choice, .lo = 0, .hi = 0, .atMost = nullptr,
     .unit = "", .label = "given as",
     .tooltip = "Coefficients: measured absorption and scattering per mm.\n"
                "Radius: Blender's Subsurface Radius (RANDOM_WALK) with the base colour as the subsurface albedo;\n"
                "the coefficients are then derived from them as Cycles derives its volume.",
     .doc = "which form gives the stone's scattering: `\"coefficients\"` (`sigma_a_mm`, `sigma_s_mm` as given) or "
            "`\"radius\"` (derived from `base_color`, `subsurface_radius_mm`, `ior` as Cycles derives them, below). "
            "Without it, an object that gives `subsurface_radius_mm` selects the radius form, one that gives "
            "`sigma_a_mm`/`sigma_s_mm` the coefficient form; both without `scattering` is an error",
     .modes = kMarble, .passes = kLightingPassBit | kBlurPassBit, .uniform = nullptr, .choices = kScatteringForm,
     .slider = {}, MARBLE_FIELD(ScatteringParams::scattering)},

    // --- physically based marble: gloss ---
    {.key = "roughness", .group = ParamGroup::Gloss, .type = ParamType::Float, .lo = 0.0, .hi = 1.0, .atMost = nullptr,
     .unit = "", .label = "roughness",
     .tooltip = "Microfacet roughness (GGX alpha = roughness^2): polished 0.05-0.15 gives a sharp highlight, honed "
                "0.4-0.6 a broad sheen.",
     .doc = "perceptual roughness, GGX α = roughness²; polished 0.05–0.15, honed 0.4–0.6; also how blurred the "
            "environment's reflection is (an `.hdr` map: its prefiltered level)",
     .modes = kMarble, .passes = kPostPassBit, .uniform = "u_roughness", .choices = {}, .slider = {0.0f, 1.0f, false},
     MARBLE_FIELD(GlossParams::roughness)},
};

#undef MARBLE_FIELD

template <typename Group>
bool equalGroup(const Material& a, const Material& b) {
  return static_cast<const Group&>(a) == static_cast<const Group&>(b);
}
template <typename Group>
void assignGroup(Material& to, const Material& from) {
  static_cast<Group&>(to) = static_cast<const Group&>(from);
}
bool equalIdentity(const Material& a, const Material& b) { return a.name == b.name && a.description == b.description; }
void assignIdentity(Material& to, const Material& from) {
  to.name = from.name;
  to.description = from.description;
}

const ParamGroupDesc kGroups[] = {
    {ParamGroup::Identity, "Identity", "the preset's name and description; no pass reads them", &equalIdentity,
     &assignIdentity},
    {ParamGroup::Pattern, "Pattern (paper 3.1)", "the pattern's evaluation: the albedo pass, or `marble`'s post pass",
     &equalGroup<PatternParams>, &assignGroup<PatternParams>},
    {ParamGroup::BaseColour, "Base colour",
     "with the pattern; `floor`; `marble`'s lighting pass (the bounce's emitters, the radius form's albedo)",
     &equalGroup<BaseColourParams>, &assignGroup<BaseColourParams>},
    {ParamGroup::Colour, "Colour", "with the pattern", &equalGroup<ColourParams>, &assignGroup<ColourParams>},
    {ParamGroup::VeinModel, "Vein model", "with the pattern, when vein_model is network or breccia",
     &equalGroup<VeinModelParams>, &assignGroup<VeinModelParams>},
    {ParamGroup::PaperModel, "The paper's model (3.2, 3.3, 4)",
     "the lighting pass of `paper`, `subsurface` and `reflectance`", &equalGroup<PaperModelParams>,
     &assignGroup<PaperModelParams>},
    {ParamGroup::Comparison, "Comparison models", "the lighting pass of `phong` and `oren-nayar`",
     &equalGroup<ComparisonParams>, &assignGroup<ComparisonParams>},
    {ParamGroup::Scattering, "Scattering (marble)", "`marble`'s lighting pass and subsurface blur (ior: also its post pass)",
     &equalGroup<ScatteringParams>, &assignGroup<ScatteringParams>},
    {ParamGroup::Gloss, "Gloss (marble)", "`marble`'s post pass alone", &equalGroup<GlossParams>,
     &assignGroup<GlossParams>},
};
static_assert(std::size(kGroups) == kParamGroupCount);

const char* groupKey(ParamGroup g) {
  switch (g) {
    case ParamGroup::Identity: return "identity";
    case ParamGroup::Pattern: return "pattern";
    case ParamGroup::BaseColour: return "base-colour";
    case ParamGroup::Colour: return "colour";
    case ParamGroup::VeinModel: return "veins";
    case ParamGroup::PaperModel: return "paper";
    case ParamGroup::Comparison: return "comparison";
    case ParamGroup::Scattering: return "scattering";
    case ParamGroup::Gloss: return "gloss";
  }
  return "";
}

// Ranges are doubles (4294967295 must print whole); values are floats (0.93f must print 0.93).
std::string number(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}
std::string number(float v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string docModes(ModeSet modes) {
  if (modes == 0) return "—";
  if ((modes & kShadingModes) != kShadingModes) return modeNames(modes);
  const ModeSet rest = modes & ~kShadingModes;
  return "every shading mode" + (rest ? " and " + modeNames(rest) : std::string());
}

std::string rangeText(const ParamDesc& p) {
  const std::string hi = p.atMost ? std::string("`") + p.atMost + "`" : number(p.hi);
  switch (p.type) {
    case ParamType::Text: return "string";
    case ParamType::UInt:
    case ParamType::Int: return "whole number " + number(p.lo) + " … " + hi;
    case ParamType::Float: return number(p.lo) + " … " + hi;
    case ParamType::Vec3:
    case ParamType::Colour: return "3 numbers " + number(p.lo) + " … " + hi;
    case ParamType::Choice: {
      std::string s;
      for (const auto& c : p.choices) s += (s.empty() ? "`\"" : ", `\"") + std::string(c.name) + "\"`";
      return s;
    }
  }
  return "";
}

std::string escapeCell(std::string s) {
  for (size_t i = 0; (i = s.find('|', i)) != std::string::npos; i += 2) s.replace(i, 1, "\\|");
  return s;
}

std::string docTable(ParamGroup g) {
  const Material defaults;
  // "Every shading mode": the modes that show the marble's colour (modeShowsAlbedo).
  std::string t = "| key | meaning | unit | range | default | read by modes |\n| --- | --- | --- | --- | --- | --- |\n";
  for (const auto& p : materialParams()) {
    if (p.group != g) continue;
    const std::string def = p.type == ParamType::Text ? "`\"" + std::get<std::string>(p.get(defaults)) + "\"`"
                                                      : "`" + formatValue(p, p.get(defaults)) + "`";
    t += std::string("| `") + p.key + "` | " + escapeCell(p.doc) + (p.inactive ? std::string("; ") + p.inactive : std::string()) + " | " + p.unit + " | " + rangeText(p) + " | " +
         def + " | " + docModes(p.modes) + " |\n";
  }
  return t;
}

}  // namespace

std::span<const ParamDesc> materialParams() { return kParams; }

const ParamDesc* findParam(std::string_view key) {
  for (const auto& p : kParams)
    if (key == p.key) return &p;
  return nullptr;
}

std::span<const ParamGroupDesc> paramGroups() { return kGroups; }
const ParamGroupDesc& groupOf(ParamGroup g) { return kGroups[static_cast<size_t>(g)]; }

GroupSet groupsRead(uint32_t passes, RenderMode mode) {
  GroupSet s = 0;
  for (const auto& p : kParams)
    if ((p.passes & passes) != 0 && modeReads(p, mode)) s |= groupBit(p.group);
  return s;
}

bool sameGroups(const Material& a, const Material& b, GroupSet groups) {
  for (const auto& g : kGroups)
    if ((groups & groupBit(g.id)) != 0 && !g.equal(a, b)) return false;
  return true;
}

bool modeReads(const ParamDesc& p, RenderMode mode) { return (p.modes & modeBit(mode)) != 0; }

std::string modeNames(ModeSet modes) {
  std::string s;
  for (size_t i = 0; i < renderModeNames().size(); ++i)
    if ((modes & (1u << i)) != 0) s += (s.empty() ? "" : ", ") + renderModeNames()[i];
  return s;
}

const char* choiceName(const ParamDesc& p, long long value) {
  for (const auto& c : p.choices)
    if (c.value == value) return c.name;
  return p.choices.empty() ? "" : p.choices.front().name;
}

std::string formatValue(const ParamDesc& p, const ParamValue& v) {
  switch (p.type) {
    case ParamType::Text: return std::get<std::string>(v);
    case ParamType::UInt:
    case ParamType::Int: return std::to_string(std::get<long long>(v));
    case ParamType::Choice: return std::string("\"") + choiceName(p, std::get<long long>(v)) + "\"";
    case ParamType::Float: return number(std::get<float>(v));
    case ParamType::Vec3:
    case ParamType::Colour: {
      const glm::vec3 c = std::get<glm::vec3>(v);
      return "[" + number(c.x) + ", " + number(c.y) + ", " + number(c.z) + "]";
    }
  }
  return "";
}

std::string withMaterialDocTables(const std::string& text) {
  std::string out;
  size_t at = 0;
  while (true) {
    const size_t open = text.find("<!-- params:", at);
    if (open == std::string::npos) break;
    const size_t openEnd = text.find("-->", open);
    const size_t close = text.find("<!-- /params -->", openEnd);
    if (openEnd == std::string::npos || close == std::string::npos) break;
    const std::string name = text.substr(open + 12, openEnd - open - 12);
    std::string table;
    for (const auto& g : kGroups)
      if (name == std::string(groupKey(g.id)) + " ") table = docTable(g.id);
    if (table.empty()) table = "(no parameter group '" + name + "')\n";
    out += text.substr(at, openEnd + 3 - at) + "\n" + table;
    at = close;
  }
  return out + text.substr(at);
}

}  // namespace marble
