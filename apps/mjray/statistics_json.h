#pragma once
/// The statistics as JSON (--stats-json, the live page, mjray-mpi's per-rank figures), written
/// by a JSON library: valid whatever the locale, the text in names or a NaN.

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "job_statistics.h"

namespace mjray {

/// A JSON value whose objects keep their keys in the order they were added.
using Json = nlohmann::ordered_json;

/// One job's statistics as a JSON object.
Json statistics_object(const JobStatistics& s);

/// `value` as compact JSON text; bytes of a string that are not UTF-8 are replaced (U+FFFD).
std::string json_text(const Json& value);

/// Writes the list of job statistics as a JSON array of objects, one per line. Throws
/// OutputError.
void write_statistics_json(const std::vector<JobStatistics>& jobs, const std::filesystem::path& path);

}  // namespace mjray
