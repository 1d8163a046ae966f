#pragma once
/// Everything a driver decides about how the jobs of a scene render, apart from the scene.

#include <filesystem>
#include <optional>

#include "mjray/accel/make_accelerator.h"
#include "mjray/integrator/photon/photon_settings.h"
#include "mjray/integrator/whitted_integrator.h"
#include "mjray/io/encode_options.h"
#include "mjray/render/image_render.h"

namespace mjray {

/// Where images go and how they are encoded.
struct OutputOptions {
  std::optional<std::filesystem::path> output;  ///< --output: the file of the scene's only image
  std::optional<std::filesystem::path> outdir;  ///< --outdir: the folder of every image
  /// Images the script names must resolve (links and ".." resolved) inside the script's
  /// folder tree or the working directory's; off with --unsafe-lua.
  bool confine_script_outputs = true;
  EncodeOptions encoding;
};

/// What the command line sets over every job's camera and image size.
struct ViewOverrides {
  std::optional<float> aperture_radius;  ///< --aperture: the thin lens's radius, over gr.lens's
  std::optional<float> focus_distance;   ///< --focus-distance: over gr.lens's
  std::optional<int> width, height;      ///< --size WxH: over gr.render's, same camera (vertical field kept)
};

/// --frames A-B:STEP: the gr.render calls to render, 1-based in script order.
struct FrameRange {
  int first = 1;
  std::optional<int> last;  ///< unset: the last call
  int step = 1;
};

/// The options of every job of one run.
struct JobOptions {
  AcceleratorOptions accel;
  IntegratorSettings integrator;
  PhotonSettings photons;  ///< --caustics, --gi
  RenderSettings render;  ///< with the --crop window (render.crop)
  OutputOptions outputs;
  ViewOverrides view;
  std::optional<FrameRange> frames;  ///< unset: every gr.render call
};

}  // namespace mjray
