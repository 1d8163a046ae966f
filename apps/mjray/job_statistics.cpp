#include "job_statistics.h"

#include <cstdio>
#include <fstream>
#include <utility>

#include <sys/resource.h>

#include "mjray/core/error.h"
#include "mjray/io/atomic_file.h"

namespace mjray {

double JobStatistics::rays_per_second() const {
  return render.seconds > 0 ? double(render.rays.total()) / render.seconds : 0;
}

uint64_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

namespace {

constexpr double kMiB = 1024.0 * 1024.0;

/// The summary's photon lines, or nothing without photon maps.
std::string photon_text(const JobStatistics& s) {
  if (!s.photons) return "";
  const PhotonStatistics& p = *s.photons;
  char text[512];
  std::snprintf(text, sizeof text,
                "  photons   caustic %llu emitted, %llu stored; global %llu emitted, %llu stored, %llu irradiance "
                "samples; %.1f MiB\n"
                "  photon pass %.3fs: trace %.3fs (%llu rays), kd-trees %.3fs, irradiance %.3fs\n",
                (unsigned long long)p.caustic_emitted, (unsigned long long)p.caustic_stored,
                (unsigned long long)p.global_emitted, (unsigned long long)p.global_stored,
                (unsigned long long)p.irradiance_samples, double(p.memory_bytes) / kMiB, p.seconds(), p.seconds_trace,
                (unsigned long long)p.rays, p.seconds_build, p.seconds_irradiance);
  return text;
}

/// The photon fields of a job's JSON object (with a leading comma), or nothing.
std::string photon_json(const JobStatistics& s) {
  if (!s.photons) return "";
  const PhotonStatistics& p = *s.photons;
  const std::pair<const char*, double> fields[] = {
      {"photons_caustic_emitted", double(p.caustic_emitted)}, {"photons_caustic_stored", double(p.caustic_stored)},
      {"photons_global_emitted", double(p.global_emitted)},   {"photons_global_stored", double(p.global_stored)},
      {"photon_irradiance_samples", double(p.irradiance_samples)}, {"photon_rays", double(p.rays)},
      {"seconds_photons", p.seconds()},                        {"seconds_photon_trace", p.seconds_trace},
      {"seconds_photon_build", p.seconds_build},               {"seconds_photon_irradiance", p.seconds_irradiance},
      {"photon_map_bytes", double(p.memory_bytes)}};
  std::string out;
  for (const auto& [key, value] : fields) {
    char field[96];
    std::snprintf(field, sizeof field, ", \"%s\": %.10g", key, value);
    out += field;
  }
  return out;
}

}  // namespace

std::string summary_text(const JobStatistics& s) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "mjray: wrote %s\n"
                "  time      %.3fs total: parse %.3fs, build %.3fs (%s, %u primitives), render %.3fs on %d threads\n"
                "  rays      %llu primary, %llu secondary, %llu shadow: %.2f M rays/s\n"
                "  pixels    %llu supersampled in %d anti-aliasing passes\n"
                "  memory    %.1f MiB peak\n",
                s.image.c_str(), s.seconds_total(), s.seconds_parse, s.seconds_build, s.accel.c_str(), s.primitives,
                s.seconds_render, s.render.threads, (unsigned long long)s.render.rays.primary,
                (unsigned long long)s.render.rays.secondary, (unsigned long long)s.render.rays.shadow,
                s.rays_per_second() / 1e6, (unsigned long long)s.render.pixels_supersampled,
                s.render.antialias_passes, double(s.peak_rss_bytes) / kMiB);
  return text + photon_text(s);
}

namespace {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
      out += escaped;
    } else out += c;
  }
  return out + "\"";
}

}  // namespace

void write_statistics_json(const std::vector<JobStatistics>& jobs, const std::filesystem::path& path) {
  std::string out = "[\n";
  for (size_t i = 0; i < jobs.size(); ++i) {
    const JobStatistics& s = jobs[i];
    char numbers[1024];
    std::snprintf(numbers, sizeof numbers,
                  "\"seconds_total\": %.6f, \"seconds_parse\": %.6f, \"seconds_build\": %.6f, "
                  "\"seconds_render\": %.6f, \"primitives\": %u, \"threads\": %d, \"rays_primary\": %llu, "
                  "\"rays_secondary\": %llu, \"rays_shadow\": %llu, \"rays_per_second\": %.1f, "
                  "\"pixels_supersampled\": %llu, \"peak_rss_bytes\": %llu",
                  s.seconds_total(), s.seconds_parse, s.seconds_build, s.seconds_render, s.primitives,
                  s.render.threads, (unsigned long long)s.render.rays.primary,
                  (unsigned long long)s.render.rays.secondary, (unsigned long long)s.render.rays.shadow,
                  s.rays_per_second(), (unsigned long long)s.render.pixels_supersampled,
                  (unsigned long long)s.peak_rss_bytes);
    out += "  {\"image\": " + json_string(s.image) + ", \"accel\": " + json_string(s.accel) + ", " + numbers +
           photon_json(s) + "}";
    out += i + 1 < jobs.size() ? ",\n" : "\n";
  }
  out += "]\n";
  write_file_atomically(path, out);
}

}  // namespace mjray
