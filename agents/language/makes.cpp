// The makes and models users name ("a white Tesla Model 3", "two range rovers", "a Transit").
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "agents/language/lexicon.hpp"
#include "agents/language/makes.hpp"
#include "agents/language/text.hpp"

namespace chatsim::agents::lexicon {
namespace detail {

std::filesystem::path vocabulary_file() {
  if (const char* env = std::getenv("CHATSIM_PROMPTS"); env != nullptr && *env != '\0')
    return std::filesystem::path(env) / "vehicles.json";
  return std::filesystem::path(CHATSIM_PROMPTS_DIR) / "vehicles.json";
}

std::vector<Make> load_makes() {
  const auto file = vocabulary_file();
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read the vehicle vocabulary " + file.string() +
                                    " (set CHATSIM_PROMPTS to the agents/prompts folder)");
  std::vector<Make> out;
  try {
    const auto doc = nlohmann::json::parse(in);
    for (const auto& m : doc.at("makes")) {
      Make make{m.at("make"), m.at("type"), {}, {}, {}};
      for (const auto& n : m.at("names")) make.names.push_back(text::words(n.get<std::string>()));
      // "ambiguous": true (every name) or the list of names that are also ordinary words.
      const auto amb = m.value("ambiguous", nlohmann::json(false));
      if (amb.is_boolean() && amb.get<bool>()) make.ambiguous = make.names;
      if (amb.is_array())
        for (const auto& n : amb) make.ambiguous.push_back(text::words(n.get<std::string>()));
      for (const auto& [model, type] : m.at("models").items()) make.models.emplace_back(text::words(model), type);
      std::stable_sort(make.models.begin(), make.models.end(),
                       [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
      out.push_back(std::move(make));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not a vehicle vocabulary (makes[].make, type, names, models): " +
                             e.what());
  }
  return out;
}

const std::vector<Make>& makes() {
  static const std::vector<Make> m = load_makes();
  return m;
}

bool words_at(const std::vector<std::string>& w, size_t at, const std::vector<std::string>& phrase) {
  if (phrase.empty() || at + phrase.size() > w.size()) return false;
  for (size_t k = 0; k < phrase.size(); ++k)
    if (w[at + k] != phrase[k]) return false;
  return true;
}

bool words_at_plural(const std::vector<std::string>& w, size_t at, const std::vector<std::string>& phrase) {
  if (phrase.empty() || at + phrase.size() > w.size()) return false;
  for (size_t k = 0; k + 1 < phrase.size(); ++k)
    if (w[at + k] != phrase[k]) return false;
  const std::string& last = w[at + phrase.size() - 1];
  return last == phrase.back() + "s" || last == phrase.back() + "es";
}

bool is_unit_word(const std::string& w) {
  static const char* kUnits[] = {"m",   "meter",   "meters",  "km",     "km/h", "mph",
                                 "m/s", "degrees", "degree", "cm", "feet", "ft"};
  for (const char* u : kUnits)
    if (w == u) return true;
  return false;
}

bool is_vehicle_determiner(const std::string& w) {
  return w == "a" || w == "an" || w == "the" || w == "another" || w == "some";
}

bool is_vehicle_premodifier(const std::string& w) {
  static const char* kWords[] = {"new",  "old",   "big",    "small", "little", "dark",
                                 "light", "bright", "shiny", "brand", "second"};
  return std::any_of(std::begin(kWords), std::end(kWords), [&](const char* k) { return w == k; });
}

}  // namespace detail

namespace {

using detail::Make;
using detail::makes;
using detail::words_at;
using detail::is_unit_word;
using detail::words_at_plural;

// The model named right after a make ("x5", "model y", "mx 5"), not a number that is a distance.
std::optional<std::pair<size_t, std::string>> model_after(const Make& make, const std::vector<std::string>& w,
                                                         size_t at, bool* plural = nullptr) {
  for (const auto& [words, type] : make.models) {
    const bool exact = words_at(w, at, words);
    if (!exact && !(plural != nullptr && words_at_plural(w, at, words))) continue;
    if (at + words.size() < w.size() && is_unit_word(w[at + words.size()])) continue;
    if (plural != nullptr) *plural = !exact;
    return std::make_pair(words.size(), type);
  }
  return std::nullopt;
}

struct ModelEntry {
  const Make* make;
  std::vector<std::string> words;
  std::string type;
};

// Models that name one make only and are not a bare number or a one- or two-letter word ("3", "x5"
// are; "prius", "model 3", "transit" count), longest first.
const std::vector<ModelEntry>& distinct_models() {
  static const std::vector<ModelEntry> out = [] {
    std::vector<ModelEntry> all;
    for (const auto& make : makes())
      for (const auto& [words, type] : make.models) {
        const bool bare = words.size() == 1 && (words[0].size() < 3 || text::is_number_word(words[0]));
        if (!bare) all.push_back({&make, words, type});
      }
    std::vector<ModelEntry> unique;
    for (const auto& e : all) {
      const auto n = std::count_if(all.begin(), all.end(), [&](const ModelEntry& x) { return x.words == e.words; });
      const bool also_a_make = std::any_of(makes().begin(), makes().end(), [&](const Make& m) {
        return std::find(m.names.begin(), m.names.end(), e.words) != m.names.end();
      });
      if (n == 1 && !also_a_make) unique.push_back(e);
    }
    std::stable_sort(unique.begin(), unique.end(),
                     [](const ModelEntry& a, const ModelEntry& b) { return a.words.size() > b.words.size(); });
    return unique;
  }();
  return out;
}

// "park a white Transit", "a Prius behind the bus": a model named without its make, where a vehicle
// noun belongs (after an article, a number or colour words). A model that is also an English word
// ("transit", "escape") must end its noun phrase: "the escape lane" names no Ford.
std::optional<BrandMention> model_alone(const std::vector<std::string>& w, size_t at) {
  size_t before = at;
  while (before > 0 && (is_color_word(w[before - 1]) || detail::is_vehicle_premodifier(w[before - 1]))) --before;
  if (before == 0) return std::nullopt;
  const std::string& det = w[before - 1];
  if (!(detail::is_vehicle_determiner(det) || det == "one" || (text::is_number_word(det) && before < at)))
    return std::nullopt;
  for (const auto& e : distinct_models()) {
    if (!words_at(w, at, e.words)) continue;
    const size_t end = at + e.words.size();
    if (end < w.size() && is_unit_word(w[end])) continue;
    const bool english = e.words.size() == 1 && is_english_word(e.words[0]);
    if (english && end < w.size() && is_english_word(w[end]) && find_types({w[end]}).empty() &&
        !text::has_any({w[end]}, {"in", "on", "at", "to", "into", "behind", "beside", "next", "near", "by", "from",
                                  "with", "ahead", "parked", "driving", "coming", "going", "heading", "that",
                                  "which", "and", "toward", "towards", "please", "instead", "too", "there"}))
      continue;
    return BrandMention{e.make->brand, "", e.type, at, end, false};
  }
  return std::nullopt;
}
}  // namespace

std::vector<BrandMention> find_brands(const std::vector<std::string>& w) {
  std::vector<BrandMention> out;
  for (size_t at = 0; at < w.size(); ++at) {
    for (const auto& make : makes()) {
      size_t n = 0;
      bool plural = false;
      const std::vector<std::string>* matched = nullptr;
      for (const auto& name : make.names)
        if (words_at(w, at, name) && name.size() > n) {
          n = name.size();
          matched = &name;
        }
      // "two range rovers": a make's name in the plural, when nothing else matched.
      if (n == 0)
        for (const auto& name : make.names)
          if (name.size() > 1 && words_at_plural(w, at, name)) {
            n = name.size();
            matched = &name;
            plural = true;
          }
      if (n == 0) continue;
      const bool ambiguous = std::find(make.ambiguous.begin(), make.ambiguous.end(), *matched) != make.ambiguous.end();
      bool model_plural = false;
      const auto model = plural ? std::nullopt : model_after(make, w, at + n, &model_plural);
      plural = plural || model_plural;
      const bool noun_follows = at + n < w.size() && !find_types({w[at + n]}).empty();
      // A make that is also an ordinary word ("man", "seat") counts only before a model or a noun.
      if (ambiguous && !model && !noun_follows) continue;
      if (make.brand == "mini" && at + n < w.size() && (w[at + n] == "van" || w[at + n] == "bus")) continue;
      std::string said = text::join(*matched);
      if (said == make.brand || text::join(text::words(make.brand)) == said) said.clear();
      const size_t end = at + n + (model ? model->first : 0);
      BrandMention m{make.brand, said, model ? model->second : make.type, at, end, plural};
      out.push_back(m);
      at = m.end - 1;
      break;
    }
    if (!out.empty() && out.back().end > at) continue;
    if (const auto m = model_alone(w, at)) {
      out.push_back(*m);
      at = m->end - 1;
    }
  }
  return out;
}

std::string make_display_name(const std::string& brand) {
  for (const auto& make : makes())
    if (make.brand == brand && !make.names.empty()) return text::join(make.names.front());
  return brand;
}

}  // namespace chatsim::agents::lexicon
