#include "game/trial/DeviceProfiles.h"

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <set>
#include <sstream>
#include <system_error>

#include "engine/script/DeviceProfileLoader.h"
#include "engine/script/ScriptError.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

// DeviceSpec names are never freed (the loop and recordings keep the
// pointer): a profile's model is kept for the life of the program. A few
// names per run at most.
const char* keptName(const std::string& name) {
  static std::mutex guard;
  static std::set<std::string> names;
  const std::lock_guard<std::mutex> lock(guard);
  return names.insert(name).first->c_str();
}

bool namesAFile(const std::string& text) {
  return text.find('/') != std::string::npos || fs::path(text).extension() == ".lua";
}

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace

std::vector<fs::path> deviceProfileFolders() {
  std::vector<fs::path> folders;
  if (const char* env = std::getenv("HEMIROLL_DEVICES"); env && *env) folders.emplace_back(env);
  folders.emplace_back("devices");
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    folders.push_back(exe.parent_path() / "devices");
    folders.push_back(exe.parent_path().parent_path() / "devices");
  }
  return folders;
}

std::vector<std::string> deviceProfileNames() {
  std::set<std::string> names;
  std::error_code ec;
  for (const fs::path& folder : deviceProfileFolders())
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().extension() == ".lua") names.insert(it->path().stem().string());
  return {names.begin(), names.end()};
}

task::DeviceProfileDef loadDeviceProfile(const std::string& nameOrFile) {
  if (nameOrFile.empty()) throw script::ScriptError("an empty device profile name (try generic, touch, omega3, ...)");
  if (namesAFile(nameOrFile)) return script::DeviceProfileLoader().loadFile(nameOrFile);
  std::error_code ec;
  std::string searched, known;
  for (const fs::path& folder : deviceProfileFolders()) {
    const fs::path file = folder / (nameOrFile + ".lua");
    if (fs::is_regular_file(file, ec)) return script::DeviceProfileLoader().loadFile(file.string());
    searched += (searched.empty() ? "" : ", ") + folder.string();
  }
  for (const std::string& n : deviceProfileNames()) known += (known.empty() ? "" : ", ") + n;
  throw script::ScriptError("unknown device profile '" + nameOrFile + "': no " + nameOrFile + ".lua in " + searched +
                            (known.empty() ? std::string(" (none holds a profile)") : "; known profiles: " + known));
}

task::DeviceProfileDef loadProtocolDeviceProfile(const std::string& nameOrFile, const std::string& protocolPath) {
  std::error_code ec;
  const fs::path beside = fs::path(protocolPath).parent_path() / nameOrFile;
  if (fs::path(nameOrFile).extension() == ".lua" && fs::path(nameOrFile).is_relative() && fs::is_regular_file(beside, ec))
    return script::DeviceProfileLoader().loadFile(beside.string());
  return loadDeviceProfile(nameOrFile);
}

haptics::DeviceSpec deviceSpecOf(const task::DeviceProfileDef& p) {
  haptics::DeviceSpec spec;
  spec.name = keptName(p.model);
  spec.maxForce = p.peakForceN;
  spec.maxStiffness = p.maxStiffnessNPerM;
  spec.workspaceRadius = 0.5 * std::min({p.workspaceWidthM, p.workspaceDepthM, p.workspaceHeightM});
  spec.hasForceOutput = true;
  return spec;
}

haptics::SafetyDef safetyOf(const task::DeviceProfileDef& p, haptics::SafetyDef base) {
  base.maxForceRate = p.maxForceRateNPerS;
  base.workspaceHalfWidth = 0.5 * p.workspaceWidthM;
  base.workspaceHalfDepth = 0.5 * p.workspaceDepthM;
  base.workspaceHalfHeight = 0.5 * p.workspaceHeightM;
  base.workspaceMargin = p.workspaceMarginM;
  base.continuousForce = p.continuousForceN;
  base.aboveContinuousLimit = p.aboveContinuousLimitS;
  return base;
}

std::string couplingRefusal(const task::DeviceProfileDef& p, const physics::CouplingDef& c, const std::string& level) {
  if (c.visualOnly) return "";  // nothing is rendered
  const bool m3 = c.method == physics::ForceMethod::M3;
  const double stiffest = c.stiffness * (m3 ? std::max(1.0, c.alpha) : 1.0);
  const std::string device = "the " + p.model + "'s";
  if (stiffest > p.maxStiffnessNPerM) {
    const std::string asked = m3 && c.alpha > 1.0
                                  ? "a coupling stiffness of " + number(stiffest) + " N/m (k_r " + number(c.stiffness) +
                                        " N/m times alpha " + number(c.alpha) + ")"
                                  : "a coupling stiffness k_r of " + number(c.stiffness) + " N/m";
    return level + " asks for " + asked + ", above " + device + " maximum stiffness of " +
           number(p.maxStiffnessNPerM) + " N/m (" + p.source + ")";
  }
  if (p.maxDampingNsPerM && c.damping > *p.maxDampingNsPerM)
    return level + " asks for a coupling damping k_v of " + number(c.damping) + " N s/m, above " + device +
           " maximum damping of " + number(*p.maxDampingNsPerM) + " N s/m (" + p.source + ")";
  return "";
}

}  // namespace hemiroll::game
