// Which vehicle words mean: added vehicles by name, colour, order or pronoun, and recorded ones
// (through the deletion agent) as anchors for placing another relative to them.
#include <algorithm>

#include "agents/language/lexicon.hpp"
#include "agents/language/text.hpp"
#include "agents/manager/classify.hpp"
#include "agents/manager/manager.hpp"

namespace chatsim::agents::manager {

using nlohmann::json;

namespace {

json anchor_json(const AddedVehicle& a) {
  const auto& p0 = a.trajectory.front();
  return {{"id", a.id}, {"x", p0["x"]}, {"y", p0["y"]}, {"yaw", p0["yaw"]}, {"size_lwh", a.asset["size_lwh"]},
          {"speed_mps", a.speed_mps}, {"wrong_way", a.resolved.value("wrong_way", false)}};
}

// "the first one", "the second one", "the last one": which of a batch, by its order.
std::optional<size_t> ordinal_one(const std::vector<std::string>& w, size_t n) {
  if (n == 0 || !text::has_any(w, {"one", "ones"}) || !lexicon::find_types(w).empty() ||
      !lexicon::find_colors(w).empty() || !lexicon::find_brands(w).empty())
    return std::nullopt;
  static const char* ordinals[] = {"first", "second", "third", "fourth", "fifth"};
  for (size_t k = 0; k < 5; ++k)
    if (text::has_phrase(w, ordinals[k])) return k < n ? std::optional<size_t>(k) : std::nullopt;
  if (text::has_phrase(w, "last")) return n - 1;
  return std::nullopt;
}

}  // namespace

// "remove the waiting cars, then add a police car where the first one was": with nothing added
// yet, "the first one" is of the vehicles removed last.
std::optional<json> Manager::ordinal_of_removed(Conversation& c, const std::string& reference) {
  if (!c.added.empty() || c.removal_batches.empty()) return std::nullopt;
  const auto k = ordinal_one(text::words(reference), c.removal_batches.back().size());
  if (!k) return std::nullopt;
  const auto out = call("deletion", c, "locate", {{"ids", json::array({c.removal_batches.back()[*k]})}});
  if (!out.ok || out.result.value("objects", json::array()).empty()) return std::nullopt;
  const json anchor = out.result["objects"][0];
  c.recorded_anchors[anchor["id"].get<std::string>()] = anchor;
  return anchor;
}

std::string Manager::colours_of_references(Conversation& c, const std::string& text) {
  const auto w = text::words(text);
  size_t len = 0;
  const size_t at = text::find_any(w, {"same color as", "same shade as", "same paint as"}, &len);
  if (at == std::string::npos) return text;
  size_t end = at + len;
  while (end < w.size() && w[end] != "and" && w[end] != "but" && w[end] != "with") ++end;
  const auto anchor = find_anchor(c, text::join(w, at + len, end), -1);
  if (!anchor || !anchor->contains("color_rgb")) return text;
  const size_t from = at > 0 && w[at - 1] == "the" ? at - 1 : at;
  return text::join(w, 0, from) + " " + lexicon::color_class((*anchor)["color_rgb"].get<lexicon::Rgb>()) + " " +
         text::join(w, end);
}

std::optional<json> Manager::find_anchor(Conversation& c, const std::string& reference, int except) {
  if (const auto it = c.recorded_anchors.find(reference); it != c.recorded_anchors.end()) return it->second;
  if (reference == "removed") {  // "in its place": the vehicle removed last
    if (c.removal_batches.empty()) return std::nullopt;
    const auto out = call("deletion", c, "locate", {{"ids", c.removal_batches.back()}});
    if (!out.ok || out.result.value("objects", json::array()).empty()) return std::nullopt;
    const json anchor = out.result["objects"][0];
    c.recorded_anchors[anchor["id"].get<std::string>()] = anchor;
    return anchor;
  }
  if (const auto removed = ordinal_of_removed(c, reference)) return removed;
  auto ref = resolve(c, reference);
  ref.erase(std::remove(ref.begin(), ref.end(), except), ref.end());
  if (!ref.empty()) return anchor_json(c.added[size_t(ref.front())]);
  const auto w = text::words(reference);
  if (lexicon::find_types(w).empty() && lexicon::find_colors(w).empty() && lexicon::find_brands(w).empty())
    return std::nullopt;  // "it" with nothing added: no recorded vehicle is meant
  auto out = call("deletion", c, "select", {{"instruction", reference}, {"removed", c.removed}});
  // "where the truck was": a removed vehicle is still a place.
  if (out.ok && out.result.value("objects", json::array()).empty() && !c.removed.empty())
    out = call("deletion", c, "select", {{"instruction", reference}, {"removed", json::array()}});
  if (!out.ok || out.result.value("objects", json::array()).empty()) return std::nullopt;
  const json anchor = out.result["objects"][0];
  c.recorded_anchors[anchor["id"].get<std::string>()] = anchor;
  return anchor;
}

std::vector<int> Manager::resolve(const Conversation& c, const std::string& reference) const {
  std::vector<int> out;
  const int n = int(c.added.size());
  if (n == 0) return out;
  for (int i = 0; i < n; ++i)
    if (c.added[size_t(i)].id == reference) return {i};
  const auto w = text::words(reference);
  if (reference == "both" || text::has_phrase(w, "both")) {
    if (c.last_group.size() >= 2) return c.last_group;
    for (int i = std::max(0, n - 2); i < n; ++i) out.push_back(i);
    return out;
  }
  if (reference == "them" || text::has_any(w, {"them", "they", "all added", "all the added"})) {
    if (!c.last_group.empty()) return c.last_group;
    for (int i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  const auto brands = lexicon::find_brands(w);
  const auto types = lexicon::find_types(w);
  const auto colors = lexicon::find_colors(w);
  static const char* ordinals[] = {"first", "second", "third", "fourth", "fifth"};
  for (int k = 0; k < 5; ++k)
    if (text::has_phrase(w, ordinals[k]) && k < n) return {k};
  if (text::has_phrase(w, "last")) return {n - 1};
  const bool typed = !types.empty() && types.front().type.type != "car" && types.front().type.type != "object";
  if (brands.empty() && !typed && colors.empty()) {
    // "it", "the added car", "the new one": the one spoken about last.
    return {c.last_ref >= 0 && c.last_ref < n ? c.last_ref : n - 1};
  }
  // The most recent added vehicle that has every named brand, type and colour; every one of them
  // for a plural ("the cones", "all the police cars").
  const bool plural = (!types.empty() && types.front().plural) || (!brands.empty() && brands.front().plural) ||
                      text::has_any(w, {"all", "every", "each"});
  for (int i = n - 1; i >= 0; --i) {
    const auto& a = c.added[size_t(i)].asset;
    const auto bw = a.value("brand_words", std::vector<std::string>{});
    if (!brands.empty() && std::find(bw.begin(), bw.end(), brands.front().brand) == bw.end()) continue;
    if (typed && a.value("type", "") != types.front().type.type) continue;
    if (!colors.empty() &&
        lexicon::color_class(a.value("color_rgb", std::array<int, 3>{0, 0, 0})) != lexicon::color_class(colors.front().rgb))
      continue;
    if (!plural) return {i};
    out.insert(out.begin(), i);
  }
  return out;
}

namespace detail {

std::string strip_reference(const std::string& text, const std::string& reference) {
  std::vector<std::string> w = text::words(text);
  std::vector<std::string> drop;
  if (reference == "both" || reference == "them") drop = {"both of them", "all of them", "each of them", "both", "them", "they"};
  else drop = {reference, "it", "its"};
  for (const auto& d : drop) {
    const size_t n = text::words(d).size();
    for (size_t at = text::find_phrase(w, d); at != std::string::npos; at = text::find_phrase(w, d))
      w.erase(w.begin() + long(at), w.begin() + long(at + n));
  }
  return text::join(w);
}

// "put it behind it", "no, in front of it": an "it" after a place word cannot be the vehicle being
// moved; it is the other one, the vehicle that placed it (do_revise).
std::string anchor_as_other(const std::string& text) {
  std::vector<std::string> w = text::words(text);
  for (const char* place : {"in front of it", "ahead of it", "behind it", "next to it", "beside it", "alongside it",
                            "past it", "opposite it"})
    if (const size_t at = text::find_phrase(w, place); at != std::string::npos)
      w[at + text::words(place).size() - 1] = kOtherVehicle;  // joined back into words below
  return text::join(w);
}

}  // namespace detail

}  // namespace chatsim::agents::manager
