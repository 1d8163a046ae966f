#include "job_statistics.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <utility>

#include <sys/resource.h>

#include "mjray/core/error.h"

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

/// What anti-aliasing did to the pixels, for the statistics' pixels line.
std::string antialiasing_text(const RenderStats& r) {
  if (r.subdivided) return "subdivided from their corners in the first pass (--aa-method subdivide)";
  if (r.refined_to_noise)
    return std::to_string(r.pixels_supersampled) + " refinements in " + std::to_string(r.antialias_passes) +
           " noise passes (--noise-threshold)";
  return std::to_string(r.pixels_supersampled) + " supersampled in " + std::to_string(r.antialias_passes) +
         " anti-aliasing passes";
}

}  // namespace

std::string summary_text(const JobStatistics& s) {
  // Appended piece by piece: GCC 12 warns falsely on "text" + a temporary string (its PR 105651).
  std::string grid;
  if (s.grid_resolution) grid.append(" ").append(std::to_string(s.grid_resolution)).append("³");
  char text[1024];
  std::snprintf(text, sizeof text,
                "mjray: wrote %s\n"
                "  time      %.3fs total: parse %.3fs, build %.3fs (%s%s, %u primitives), render %.3fs on %d threads\n"
                "  rays      %llu primary, %llu secondary, %llu shadow: %.2f M rays/s\n"
                "  pixels    %s\n"
                "  memory    %.1f MiB peak\n",
                s.image.c_str(), s.seconds_total(), s.seconds_parse, s.seconds_build, s.accel.c_str(), grid.c_str(), s.primitives,
                s.seconds_render, s.render.threads, (unsigned long long)s.render.rays.primary,
                (unsigned long long)s.render.rays.secondary, (unsigned long long)s.render.rays.shadow,
                s.rays_per_second() / 1e6, antialiasing_text(s.render).c_str(), double(s.peak_rss_bytes) / kMiB);
  std::string summary = text + photon_text(s);
  for (const RankStatistics& r : s.ranks) {
    std::snprintf(text, sizeof text,
                  "  rank %-4d %s: load %.3fs, build %.3fs, rendering %.3fs on %d threads, %llu tiles, "
                  "%llu pixels supersampled, %.2f MB sent\n",
                  r.rank, r.host.c_str(), r.seconds_load, r.seconds_build, r.seconds_rendering, r.threads,
                  (unsigned long long)r.tiles, (unsigned long long)r.pixels_supersampled, double(r.bytes_sent) / 1e6);
    summary += text;
  }
  return summary;
}

std::string frame_line(const JobStatistics& s, const std::string& frame, bool detailed) {
  char text[512];
  if (!detailed) {
    std::snprintf(text, sizeof text, "mjray: wrote %s (%s, %.2fs)\n", s.image.c_str(), frame.c_str(), s.seconds_total());
    return text;
  }
  std::snprintf(text, sizeof text,
                "mjray: wrote %s (%s): %.3fs (build %.3fs, render %.3fs), %llu rays at %.2f M rays/s, %s, "
                "%.1f MiB peak\n",
                s.image.c_str(), frame.c_str(), s.seconds_total(), s.seconds_build, s.seconds_render,
                (unsigned long long)s.render.rays.total(), s.rays_per_second() / 1e6,
                s.render.subdivided         ? "pixels subdivided"
                : s.render.refined_to_noise ? (std::to_string(s.render.pixels_supersampled) + " pixel refinements").c_str()
                                            : (std::to_string(s.render.pixels_supersampled) + " pixels supersampled").c_str(),
                double(s.peak_rss_bytes) / (1024.0 * 1024.0));
  return text;
}

std::string animation_summary(const std::vector<JobStatistics>& frames, size_t kept, bool detailed) {
  JobStatistics all;
  all.seconds_parse = frames.empty() ? 0 : frames.front().seconds_parse;
  for (const JobStatistics& s : frames) {
    all.seconds_build += s.seconds_build;
    all.seconds_render += s.seconds_render;
    all.render.seconds += s.render.seconds;
    all.render.rays += s.render.rays;
    all.render.threads = s.render.threads;
    all.render.pixels_supersampled += s.render.pixels_supersampled;
    all.render.antialias_passes += s.render.antialias_passes;
    all.render.subdivided = all.render.subdivided || s.render.subdivided;
    all.render.refined_to_noise = all.render.refined_to_noise || s.render.refined_to_noise;
    all.primitives = std::max(all.primitives, s.primitives);
    all.peak_rss_bytes = std::max(all.peak_rss_bytes, s.peak_rss_bytes);
    if (all.accel.empty()) all.accel = s.accel;
    if (s.photons) {
      PhotonStatistics& p = all.photons ? *all.photons : all.photons.emplace();
      p.caustic_emitted += s.photons->caustic_emitted;
      p.caustic_stored += s.photons->caustic_stored;
      p.global_emitted += s.photons->global_emitted;
      p.global_stored += s.photons->global_stored;
      p.irradiance_samples += s.photons->irradiance_samples;
      p.rays += s.photons->rays;
      p.seconds_trace += s.photons->seconds_trace;
      p.seconds_build += s.photons->seconds_build;
      p.seconds_irradiance += s.photons->seconds_irradiance;
      p.memory_bytes = std::max(p.memory_bytes, s.photons->memory_bytes);
    }
  }
  char head[256];
  const std::string kept_text = kept > 0 ? " (" + std::to_string(kept) + " kept)" : "";
  std::snprintf(head, sizeof head, "mjray: rendered %zu frame%s%s in %.3fs\n", frames.size(), frames.size() == 1 ? "" : "s",
                kept_text.c_str(), all.seconds_total());
  if (!detailed) return head;
  // The paragraph of one image, over every frame: its first line replaced by the head.
  const std::string paragraph = summary_text(all);
  return head + paragraph.substr(paragraph.find('\n') + 1);
}

}  // namespace mjray
