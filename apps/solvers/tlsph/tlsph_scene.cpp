// The TL-SPH solid's scene keys, each declared once where it is read.
#include "tlsph/tlsph_spec.hpp"

#include "fsi_app/material_reader.hpp"

namespace fsi::app::tlsph_plugin {

namespace {

Box read_box(Section s, const std::string& what) {
  Box b;
  b.min = s.vec2("min", "lower-left corner of " + what + ", m");
  b.max = s.vec2("max", "upper-right corner, m");
  if (!s.context().documenting() && (b.max.x() <= b.min.x() || b.max.y() <= b.min.y()))
    s.fail("max", "must lie above and right of min");
  s.finish();
  return b;
}

} // namespace

std::shared_ptr<const SolverSpec> read_tlsph(Section& s) {
  auto spec = std::make_shared<TlsphSpec>();
  TlsphSpec& t = *spec;
  const bool doc = s.context().documenting();
  t.region = read_box(s.required_block("region", "the rectangle filled with solid particles at "
                                                 "spacing dp from its lower-left corner; sides "
                                                 "tagged bottom, right, top, left"),
                      "the solid");
  OptionReader reader(s);
  tlsph::visit_options(t.options, reader);
  auto mat = s.required_block("material", "hyperelastic material (materials/)");
  read_material(mat, t.options.material);
  for (auto& box : s.list("clamped", "boxes: the particles whose reference position lies inside "
                                     "are the clamp, a support beyond the body (fixed: the body "
                                     "is clamped at the box's face, so the region extends 2 or "
                                     "more rows into the box; or they follow clamped_motion)"))
    t.clamped.push_back(read_box(box, "a clamped box"));
  t.clamped_motion = s.text("clamped_motion", "",
                            "name of a wall with a motion: the clamped particles follow its rigid "
                            "motion; empty: they stay fixed");
  t.options.interface_tags =
      s.names("interface", {}, "sides wetted by the fluid (bottom, right, top, left)");
  if (!doc) {
    const Vec2 size = t.region.max - t.region.min;
    if (t.options.dp * 3.0 > size.minCoeff())
      s.fail("dp", "fewer than 3 particles across the region (" + std::to_string(size.x()) + " x " +
                       std::to_string(size.y()) + " m)");
    for (const auto& tag : t.options.interface_tags)
      if (tag != "bottom" && tag != "right" && tag != "top" && tag != "left")
        s.fail("interface", "unknown side '" + tag + "' (bottom, right, top, left)");
  }
  return spec;
}

} // namespace fsi::app::tlsph_plugin
