#include "anim/keyframe_track.h"

#include <algorithm>
#include <cmath>

#include "base/errors.h"

namespace gridifs {

const char* toString(KeyInterpolation interpolation) {
  switch (interpolation) {
    case KeyInterpolation::Step:
      return "step";
    case KeyInterpolation::Linear:
      return "linear";
    case KeyInterpolation::Smooth:
      return "smooth";
  }
  return "linear";
}

bool parseKeyInterpolation(const std::string& text, KeyInterpolation& out) {
  if (text == "step") {
    out = KeyInterpolation::Step;
  } else if (text == "linear") {
    out = KeyInterpolation::Linear;
  } else if (text == "smooth") {
    out = KeyInterpolation::Smooth;
  } else {
    return false;
  }
  return true;
}

namespace {

// The Catmull-Rom tangent at key i (units of value per second): the slope between its
// neighbours; one-sided at the ends.
double tangentAt(const std::vector<Keyframe>& keys, std::size_t i) {
  const std::size_t before = i == 0 ? 0 : i - 1;
  const std::size_t after = std::min(i + 1, keys.size() - 1);
  if (before == after) return 0.0;
  return (keys[after].v - keys[before].v) / (keys[after].t - keys[before].t);
}

}  // namespace

double KeyframeTrack::valueAt(double t) const {
  if (keys.empty()) return 0.0;
  if (t <= keys.front().t) return keys.front().v;
  if (t >= keys.back().t) return keys.back().v;
  // The segment [keys[i], keys[i+1]] that holds t.
  const auto next =
      std::upper_bound(keys.begin(), keys.end(), t, [](double time, const Keyframe& k) { return time < k.t; });
  const std::size_t i = static_cast<std::size_t>(next - keys.begin()) - 1;
  const Keyframe& a = keys[i];
  const Keyframe& b = keys[i + 1];
  const double h = b.t - a.t;
  const double u = (t - a.t) / h;
  switch (a.interp) {
    case KeyInterpolation::Step:
      return a.v;
    case KeyInterpolation::Linear:
      return a.v + u * (b.v - a.v);
    case KeyInterpolation::Smooth: {
      const double m0 = tangentAt(keys, i) * h, m1 = tangentAt(keys, i + 1) * h;
      const double u2 = u * u, u3 = u2 * u;
      return (2 * u3 - 3 * u2 + 1) * a.v + (u3 - 2 * u2 + u) * m0 + (-2 * u3 + 3 * u2) * b.v + (u3 - u2) * m1;
    }
  }
  return a.v;
}

namespace {

// The antiderivatives of the cubic Hermite basis (h00, h10, h01, h11) in u, zero at u = 0.
struct HermitePrimitive {
  double h00, h10, h01, h11;
};
HermitePrimitive hermitePrimitive(double u) {
  const double u2 = u * u, u3 = u2 * u, u4 = u3 * u;
  return {u4 / 2 - u3 + u, u4 / 4 - 2 * u3 / 3 + u2 / 2, -u4 / 2 + u3, u4 / 4 - u3 / 3};
}

// ∫ over the part [u0, u1] of segment i (keys[i] to keys[i + 1]) of the track's value, in seconds.
double segmentIntegral(const std::vector<Keyframe>& keys, std::size_t i, double u0, double u1) {
  const Keyframe& a = keys[i];
  const Keyframe& b = keys[i + 1];
  const double h = b.t - a.t;
  switch (a.interp) {
    case KeyInterpolation::Step:
      return h * a.v * (u1 - u0);
    case KeyInterpolation::Linear:
      return h * (a.v * (u1 - u0) + (b.v - a.v) * (u1 * u1 - u0 * u0) / 2);
    case KeyInterpolation::Smooth: {
      const double m0 = tangentAt(keys, i) * h, m1 = tangentAt(keys, i + 1) * h;
      const HermitePrimitive p1 = hermitePrimitive(u1), p0 = hermitePrimitive(u0);
      return h * ((p1.h00 - p0.h00) * a.v + (p1.h10 - p0.h10) * m0 + (p1.h01 - p0.h01) * b.v + (p1.h11 - p0.h11) * m1);
    }
  }
  return 0.0;
}

// ∫ from the first key's time to t of the track's value (negative before the first key).
double primitiveAt(const std::vector<Keyframe>& keys, double t) {
  const double first = keys.front().t;
  if (t <= first) return (t - first) * keys.front().v;
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) {
    const double h = keys[i + 1].t - keys[i].t;
    if (t >= keys[i + 1].t) {
      sum += segmentIntegral(keys, i, 0.0, 1.0);
      continue;
    }
    return sum + segmentIntegral(keys, i, 0.0, (t - keys[i].t) / h);
  }
  return sum + (t - keys.back().t) * keys.back().v;
}

}  // namespace

double KeyframeTrack::integral(double t0, double t1) const {
  if (keys.empty()) return 0.0;
  return primitiveAt(keys, t1) - primitiveAt(keys, t0);
}

void KeyframeTrack::validate() const {
  if (keys.empty()) throw ModelError("", "a track needs at least one key");
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::string at = "[" + std::to_string(i) + "]";
    if (!std::isfinite(keys[i].t)) throw ModelError(at + ".t", "the key's time must be a finite number");
    if (!std::isfinite(keys[i].v)) throw ModelError(at + ".v", "the key's value must be a finite number");
    if (i > 0 && keys[i].t <= keys[i - 1].t) {
      throw ModelError(at + ".t", keys[i].t == keys[i - 1].t ? "two keys share the time " + std::to_string(keys[i].t) +
                                                                   "; each key needs its own time"
                                                             : "keys must be in increasing time order");
    }
  }
}

void KeyframeTrack::setKey(const Keyframe& key) {
  const auto at =
      std::lower_bound(keys.begin(), keys.end(), key.t, [](const Keyframe& k, double time) { return k.t < time; });
  if (at != keys.end() && std::abs(at->t - key.t) <= 1e-9) {
    *at = key;
  } else {
    keys.insert(at, key);
  }
}

bool KeyframeTrack::removeKey(double t, double tolerance) {
  const auto at =
      std::find_if(keys.begin(), keys.end(), [&](const Keyframe& k) { return std::abs(k.t - t) <= tolerance; });
  if (at == keys.end()) return false;
  keys.erase(at);
  return true;
}

void remapTrackIndices(KeyframeTracks& tracks, const std::string& listPath, const std::function<int(int)>& newIndex) {
  const std::string prefix = listPath + "[";
  KeyframeTracks remapped;
  for (auto& [path, track] : tracks) {
    const std::size_t close = path.find(']', prefix.size());
    if (path.compare(0, prefix.size(), prefix) != 0 || close == std::string::npos || close == prefix.size() ||
        close - prefix.size() > 6 || path.find_first_not_of("0123456789", prefix.size()) != close) {
      remapped.emplace(path, std::move(track));
      continue;
    }
    const int to = newIndex(std::stoi(path.substr(prefix.size(), close - prefix.size())));
    if (to < 0) continue;
    remapped.emplace(prefix + std::to_string(to) + path.substr(close), std::move(track));
  }
  tracks = std::move(remapped);
}

}  // namespace gridifs
