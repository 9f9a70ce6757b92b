// The material sections of the panel: pattern, colour, subsurface, reflectance. Tooltips say
// what a parameter does physically; each section resets to the preset the material came from.
#include <algorithm>
#include <string>

#include "material_sections.h"
#include "panel_sections.h"
#include "panel_widgets.h"
#include "param_ranges.h"

namespace marble::viewer {
namespace {

std::string resetTip(const ViewerState& s, const char* what) {
  return std::string("Set the ") + what + " parameters back to preset \"" + s.presetName + "\".";
}

// The vein model (issue 16; docs/materials.md "Vein model"). Triples are (dominant, secondary, hairline).
void drawVeinModelControls(Material& m) {
  ImGui::Separator();  // ImGui 1.86 has no SeparatorText
  ImGui::TextDisabled("vein model");
  enumCombo("vein model", m.vein_model, {"paper (|sin|)", "crack network", "breccia"},
            "paper: the paper's veins, contour lines of |sin(ramp + turbulence)|.\n"
            "crack network: veins are mineral-filled fractures that fork, rejoin, swell and fade (Carrara, Calacatta).\n"
            "breccia: angular fragments of stone cemented by a matrix, cut by crack veins (Rosso Levanto, Emperador).\n"
            "The network models are solid (object space) whatever the mapping; the turbulence above warps them.");
  if (m.vein_model == VeinModel::Paper) return;
  slider3("spacing", "vein_spacing", m.vein_spacing,
          "Mean distance between cracks of each family (dominant, secondary, hairline), object units (the object is 2 across).\n"
          "Breccia: the first is the fragments' size.");
  slider3("width", "vein_width", m.vein_width,
          "Full width of each family's veins, object units: how thick the mineral filling is.\n"
          "Breccia: the first is the matrix between fragments.");
  slider3("density", "vein_density", m.vein_density,
          "Fraction of each family's cracks that are filled: 1 a closed network, low values isolated veins that end.");
  slider3("vein normal", "vein_normal", m.vein_normal,
          "Normal (object space) of the planes the dominant veins lie in: the stone's bedding.\n"
          "A cut across it shows roughly parallel veins; a cut along it broad clouds (a 'fleuri' cut).");
  slider("stretch", "vein_stretch", m.vein_stretch,
         "How much thinner the dominant cells are across the vein normal: 1 veins in every direction, high parallel veins (Statuario, Calacatta).\n"
         "The secondary family gets its square root, hairlines none.");
  slider("warp", "vein_warp", m.vein_warp,
         "How far the turbulence bends the cracks, object units: 0 straight-faced cells, high meandering, folded veins.");
  slider("pinch", "vein_pinch", m.vein_pinch,
         "How much a vein's width swells and pinches along it: 0 constant width, 1 veins that thin out and vanish.");
  slider("softness", "vein_softness", m.vein_softness,
         "Edge blur relative to the width: 0 crisp fractures, 1 veins that bleed into the ground.");
  slider("grain", "grain_amount", m.grain_amount, "Contrast of the fine calcite grain (crystals about 1.5 texels across).");
  if (m.vein_model == VeinModel::Breccia)
    slider("fragment tint", "fragment_tint", m.fragment_tint,
           "How much the fragments differ in colour, from the base toward the cloud colour.");
}

}  // namespace

void drawPatternSection(ViewerState& s) {
  Material& m = s.scene.material;
  bool reset;
  const std::string tip = resetTip(s, "pattern");
  const bool open = sectionHeader("Pattern (paper 3.1)", true, tip.c_str(), reset);
  if (reset) resetSection(m, s.presetMaterial, MaterialSection::Pattern);
  if (!open) return;
  enumCombo("mapping", m.mapping, {"planar x/z (paper)", "triplanar", "solid 3D"},
            "How the pattern meets the surface. Planar: the paper's 2D texture on x/z, stretched along y.\n"
            "Triplanar: three planar projections blended by the normal.\n"
            "Solid: a block of stone cut into the shape (veins run through edges).");
  enumCombo("noise", m.basis, {"value (paper)", "Perlin gradient"},
            "Smooth-noise basis under the turbulence. Value noise is the paper's; Perlin has fewer grid artefacts.");
  int seed = static_cast<int>(std::min<uint32_t>(m.seed, 1000000000u));
  if (ImGui::InputInt("seed", &seed)) m.seed = static_cast<uint32_t>(std::max(0, seed));
  tooltip("Seed of the white-noise lattice: another block of the same stone.");
  slider("x period", "x_period", m.x_period,
         "Vein repetitions along x. With the y period it sets the angle and spacing of the veins.\nBoth 0: turbulence alone.");
  slider("y period", "y_period", m.y_period, "Vein repetitions along y (the texture's t).");
  slider("z period", "z_period", m.z_period, "Vein repetitions along z (solid mapping only).");
  slider("turbulence", "turb_power", m.turb_power,
         "How far the turbulence bends the veins. 0 gives straight sine stripes, high values chaotic folds.");
  const ParamRange size = rangeOf("turb_size");
  ImGui::SliderFloat("turbulence size", &m.turb_size, size.lo, std::min(size.hi, static_cast<float>(m.resolution)),
                     "%.3g", ImGuiSliderFlags_Logarithmic);
  tooltip("Size of the largest turbulence octave, in texels (at most the resolution); each octave halves it.\n"
          "Large: broad swirls. Small: fine grain.");
  const ParamRange res = rangeOf("resolution");
  ImGui::SliderInt("resolution", &m.resolution, static_cast<int>(res.lo), static_cast<int>(res.hi), "%d",
                   ImGuiSliderFlags_Logarithmic);
  tooltip("Texels across the pattern: the density of the white-noise lattice. More gives finer detail.");
  m.turb_size = std::min(m.turb_size, static_cast<float>(m.resolution));  // the loader's cross-field rule
  slider("pattern scale", "pattern_scale", m.pattern_scale, "Size of the pattern on the object: larger spreads the veins out.");
  drawVeinModelControls(m);
}

void drawColourSection(ViewerState& s) {
  Material& m = s.scene.material;
  bool reset;
  const std::string tip = resetTip(s, "colour");
  const bool open = sectionHeader("Colour", true, tip.c_str(), reset);
  if (reset) resetSection(m, s.presetMaterial, MaterialSection::Colour);
  if (!open) return;
  colour("base", m.base_color, "Albedo of the stone between veins (linear RGB).");
  colour("vein", m.vein_color, "Albedo at the heart of a vein (linear RGB).");
  colour("vein 2", m.vein2_color, "Secondary vein colour, between base and vein on the ramp.");
  slider("vein sharpness", "vein_sharpness", m.vein_sharpness,
         "Exponent on the sine pattern: higher gives thinner, crisper veins; 1 is the paper.");
  slider("vein 2 amount", "vein2_amount", m.vein2_amount,
         "How much of the secondary colour the ramp uses: 0 is the paper's two-colour ramp.");
  if (m.vein_model != VeinModel::Paper) {  // vein model (issue 16)
    ImGui::TextDisabled("vein model: vein = dominant, vein 2 = secondary veins");
    colour("vein 3", m.vein3_color, "Albedo of the hairline veins (linear RGB).");
    colour("clouds", m.cloud_color, "The ground's clouds (Carrara's nuvolato) and the breccia fragments' tints (linear RGB).");
    slider("cloud amount", "cloud_amount", m.cloud_amount, "How strongly the ground clouds toward the cloud colour: 0 a plain ground.");
  }
}

void drawSubsurfaceSection(ViewerState& s) {
  Material& m = s.scene.material;
  bool reset;
  const std::string tip = resetTip(s, "subsurface");
  const bool open = sectionHeader("Subsurface (paper 3.2)", true, tip.c_str(), reset);
  if (reset) resetSection(m, s.presetMaterial, MaterialSection::Subsurface);
  if (!open) return;
  slider3("sigma_t rgb", "sigma_t", m.sigma_t,
          "Extinction per scene unit, per channel: light through thickness d keeps exp(-sigma_t * d).\n"
          "Low: translucent, glowing edges. High: opaque. Red travels further in marble than blue.\n"
          "(The object is 2 units across.)");
  slider("k_sss", "k_sss", m.k_sss, "Strength of the subsurface term: 0 = off, 1 = full.");
  slider3("sigma_a 1/mm", "sigma_a_mm", m.sigma_a_mm,
          "Measured absorption per millimetre, per channel: light lost inside the stone. Higher: darker, more coloured glow.");
  slider3("sigma_s' 1/mm", "sigma_s_mm", m.sigma_s_mm,
          "Reduced scattering per millimetre, per channel: how often light turns inside. Higher: milkier, shorter glow.");
  slider("translucency", "translucency", m.translucency,
         "Scales light transmitted through thin parts: 1 is physical, 0 opaque, above 1 exaggerated.");
}

void drawReflectanceSection(ViewerState& s) {
  Material& m = s.scene.material;
  bool reset;
  const std::string tip = resetTip(s, "reflectance");
  const bool open = sectionHeader("Reflectance (paper 3.3)", true, tip.c_str(), reset);
  if (reset) resetSection(m, s.presetMaterial, MaterialSection::Reflectance);
  if (!open) return;
  slider("k_schlick", "k_schlick", m.k_schlick,
         "Opacity of the Fresnel-Schlick reflectance over the colour: the polish. Grazing angles reflect most.");
  slider("ior", "ior", m.ior, "Index of refraction: sets F0 = ((n-1)/(n+1))^2. Calcite is 1.49-1.66 (F0 about 0.04-0.06).");
  slider("roughness", "roughness", m.roughness,
         "Microfacet roughness (GGX alpha = roughness^2): polished 0.05-0.15 gives a sharp highlight, honed 0.4-0.6 a broad sheen.");
  slider("metalness", "metalness", m.metalness, "F0 = mix(0.04, albedo, metalness). Calcite is a dielectric: keep 0.");
  enumCombo("order", m.order, {"subsurface first (paper)", "reflectance first"},
            "Which term is applied first (paper section 4). Changes how the polish tints the glow.");
  enumCombo("Schlick cos", m.schlick_cos, {"H.V (standard)", "H.N (paper)"},
            "The angle in (1 - cos)^5. The standard form uses H.V; the paper wrote H.N.");
  ImGui::TextDisabled("comparison modes");
  slider("Phong shininess", "shininess", m.shininess,
         "Specular exponent of the 'phong' render mode: higher is a smaller, sharper highlight.");
  slider("Oren-Nayar sigma", "oren_nayar_sigma", m.oren_nayar_sigma,
         "Surface roughness (radians) of the 'oren-nayar' render mode: 0 is Lambert, higher is flatter.");
}

}  // namespace marble::viewer
