#pragma once
/// What ranks say to each other, one struct per kind of message, with its encoding. Rank 0
/// sends jobs, units and the end; the other ranks answer with readiness, results, reports
/// and failures.

#include <cstdint>
#include <string>
#include <vector>

#include "job_statistics.h"
#include "work_unit.h"
#include "mjray/core/image.h"
#include "mjray/integrator/integrator.h"
#include "mjray/render/film.h"

namespace mjray {

/// The first byte of every message.
enum class MessageType : uint8_t {
  // rank 0 to the others
  kTileJob,    ///< prepare a job and render its tiles as they come
  kUnits,      ///< units of the current tile job
  kEndJob,     ///< the tile job is done: report and wait
  kFrameJob,   ///< render a whole job here and send it back
  kStopFrame,  ///< interrupted: stop the frame and send what is done
  kFinish,     ///< the run is over
  // the others to rank 0
  kReady,      ///< prepared the tile job
  kResult,     ///< a finished unit
  kJobReport,  ///< what this rank did for the tile job
  kFrameDone,  ///< a whole job, finished or stopped
  kFailed,     ///< this rank cannot go on
};

/// The type of a message (throws std::runtime_error when it is empty).
MessageType type_of(const std::string& bytes);

struct TileJobMessage {
  uint32_t job = 0;
  int32_t tile_size = 16;
};
struct UnitsMessage {
  uint32_t phase = 0;  ///< which render_tiles/render_pixels call of the job the units belong to
  std::vector<WorkUnit> units;
};
struct FrameJobMessage {
  uint32_t job = 0;
  std::string state;   ///< an encoded RenderCheckpoint to resume from; empty: from scratch
};
struct ReadyMessage {
  uint32_t job = 0;
  int32_t threads = 1;
  double seconds_build = 0;
};
struct ResultMessage {
  uint32_t phase = 0;
  WorkUnit::Kind kind = WorkUnit::Kind::kTile;
  int32_t id = 0;
  RayCounters rays;           ///< cast for this unit
  std::vector<FilmPixel> values;
};
struct FrameDoneMessage {
  uint32_t job = 0;
  bool finished = false;
  Image image;                ///< finished: the image
  std::string checkpoint;     ///< stopped: the encoded RenderCheckpoint (without fingerprint)
  JobStatistics stats;        ///< with the rendering rank as its only entry of `ranks`
};
struct FailedMessage {
  std::string text;
};

std::string encode(const TileJobMessage& m);
std::string encode(const UnitsMessage& m);
std::string encode(const FrameJobMessage& m);
std::string encode(const ReadyMessage& m);
std::string encode(const ResultMessage& m);
std::string encode(const RankStatistics& m);  ///< kJobReport
std::string encode(const FrameDoneMessage& m);
std::string encode(const FailedMessage& m);
/// A message of a type that carries nothing else (kEndJob, kStopFrame, kFinish).
std::string encode(MessageType type);

/// Decoders: each expects a message of its type (throws std::runtime_error otherwise).
TileJobMessage decode_tile_job(const std::string& bytes);
UnitsMessage decode_units(const std::string& bytes);
FrameJobMessage decode_frame_job(const std::string& bytes);
ReadyMessage decode_ready(const std::string& bytes);
ResultMessage decode_result(const std::string& bytes);
RankStatistics decode_job_report(const std::string& bytes);
FrameDoneMessage decode_frame_done(const std::string& bytes);
FailedMessage decode_failed(const std::string& bytes);

}  // namespace mjray
