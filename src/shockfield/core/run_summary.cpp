#include "shockfield/core/run_summary.hpp"

#include "shockfield/core/run_folder.hpp"

namespace shockfield {

namespace fs = std::filesystem;

Json provenance_json(const Provenance& p) {
  Json files = Json::array();
  for (const InputFileRecord& f : p.input_files)
    files.push(Json::object().set("path", f.path).set("sha256", f.sha256).set("bytes", static_cast<long long>(f.bytes)));
  Json j = Json::object();
  j.set("version", p.version).set("git_commit", p.git_commit).set("build_type", p.build_type);
  j.set("compiler", p.compiler).set("host", p.host).set("command_line", p.command_line).set("threads", p.threads);
  j.set("start_time", p.start_time);
  if (!p.end_time.empty()) j.set("end_time", p.end_time);
  return j.set("input_files", std::move(files));
}

void write_run_summary(const fs::path& folder, const fs::path& case_file, const Method& m, const std::string& status,
                       const std::string& message, const RunTally& t, const Provenance& provenance) {
  const double rate = t.wall_seconds > 0 ? static_cast<double>(t.steps) / t.wall_seconds : 0.0;
  Json rates = Json::object();
  rates.set("steps_per_second", rate).set(m.work_item_name() + "_steps_per_second", rate * m.work_items());
  if (m.ns_per_step() > 0) rates.set("ns_per_day", rate * m.ns_per_step() * 86400.0);
  Json phases = Json::object();
  phases.set("step", t.step_seconds);
  for (const PhaseTime& p : m.phase_times()) phases.set(p.name, p.seconds);
  phases.set("output", t.output_seconds).set("checkpoint", t.checkpoint_seconds);
  Json j = Json::object();
  j.set("schema_version", 1).set("method", m.name()).set("case", fs::absolute(case_file).string()).set("status", status);
  if (!message.empty()) j.set("message", message);
  j.set("steps", static_cast<long long>(m.step())).set("time", m.time()).set("time_unit", m.time_unit());
  j.set("wall_seconds", t.wall_seconds).set("rates", std::move(rates)).set("phases", std::move(phases));
  j.set("provenance", provenance_json(provenance)).set("results", m.results());
  write_file_atomically(folder / "summary.json", to_json_text(j) + "\n");
}

}  // namespace shockfield
