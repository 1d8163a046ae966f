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
  EncodeOptions encoding;
};

/// The options of every job of one run.
struct JobOptions {
  AcceleratorOptions accel;
  IntegratorSettings integrator;
  PhotonSettings photons;  ///< --caustics, --gi
  RenderSettings render;
  OutputOptions outputs;
};

}  // namespace mjray
