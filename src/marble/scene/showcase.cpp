#include "marble/scene/showcase.h"

#include "marble/scene/material_io.h"
#include "marble/scene/placement.h"

namespace marble {

Scene showcaseScene() {
  Scene s;
  s.mesh = "builtin:sculpture";  // a knot whose tube swells (broad faces) and thins (translucent parts)
  s.material = loadPreset("calacatta");
  s.mm_per_unit = 60.0f;  // a 12 cm piece: light passes through the thin parts of the tube
  placeCamera(s, 20.0f, 18.0f, 4.4f);
  // Key light behind and above, a little to the side: the thin parts glow towards the camera
  // while the studio environment lights and reflects in the faces turned to it.
  placeLight(s, 150.0f, 35.0f);
  s.render.background = {0.10f, 0.10f, 0.11f};  // charcoal, where the studio's floor fades out
  s.render.environment = Environment::Studio;
  s.render.backdrop = true;  // the studio itself behind the object, softly blurred
  s.render.ground = true;    // standing on the floor, with its shadow
  s.render.environment_intensity = 0.8f;
  return s;
}

}  // namespace marble
