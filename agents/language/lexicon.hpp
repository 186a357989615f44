#pragma once
// What words mean in this domain: colours, vehicle types and brands, scene categories.
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace chatsim::agents::lexicon {

using Rgb = std::array<int, 3>;

// The basic colour names the command cases grade by (red, orange, yellow, green, blue, purple,
// white, black, gray), judged on hue, saturation and lightness.
std::string color_class(const Rgb& rgb);

struct ColorMention {
  std::string name;      // as said, e.g. "dark blue", "silver"
  Rgb rgb{};
  size_t begin = 0, end = 0;  // word span
};
// All colour words in order ("dark blue", "light gray", "silver", "red", ...).
std::vector<ColorMention> find_colors(const std::vector<std::string>& words);

struct VehicleType {
  std::string type;          // car, suv, truck, bus, van, police, taxi, ambulance, firetruck, motorcycle, cone, barrier
  std::string category;      // the scene category an added one gets, e.g. vehicle.emergency.police
  std::string scene_prefix;  // what it selects among labelled objects, e.g. vehicle.truck
  bool living() const { return type == "pedestrian" || type == "animal"; }  // walks: never a vehicle to add
  // What the asset agent can add: no walker, no tram (labelled in some datasets only), no bare "object".
  bool addable() const { return !living() && type != "tram" && type != "object"; }
};

struct TypeMention {
  VehicleType type;
  size_t begin = 0, end = 0;
  bool plural = false;
};
// Vehicle and object nouns in order ("police car" before "car", "fire truck" before "truck").
std::vector<TypeMention> find_types(const std::vector<std::string>& words);
const VehicleType* vehicle_type(const std::string& type);

struct BrandMention {
  std::string brand;     // porsche
  std::string name;      // as said when that is another name of the make ("cupra", "vauxhall"), else ""
  std::string type;      // its usual type: car, suv, truck
  size_t begin = 0, end = 0;
  bool plural = false;   // "two range rovers", "teslas"
};
std::vector<BrandMention> find_brands(const std::vector<std::string>& words);
// A make's name as people write it ("land rover" for the make "landrover"), or the make itself.
std::string make_display_name(const std::string& brand);

// "in its place", "where it was", "in its spot": where a vehicle removed (or being removed) stood.
const std::vector<std::string>& place_of_removed_phrases();

// Words that place a vehicle relative to another ("behind the bus", "tailgating the orange car",
// "opposite the school bus"): the region (front, back, left, right; beyond: past it as seen from
// the ego; opposite: level with it across the road) and whether it follows that vehicle. What
// follows one names the other vehicle, not the one added. Tried in this order, the first found
// winning: mostly a phrase before the shorter ones it contains ("chasing after" before "after");
// "ahead of" before "just ahead of", so that "just" stays for the placement words ("just ahead").
struct Relation {
  std::string phrase;
  std::string region;
  bool chase = false;
  std::vector<std::string> words = {};  // the phrase as text::words reads it
};
const std::vector<Relation>& relation_phrases();
// Words that name something we cannot select or add (helicopter, plane, ...).
std::optional<std::string> unsupported_noun(const std::vector<std::string>& words);

bool is_color_word(const std::string& w);

// Misspelt words read as the domain word one edit away ("delte" -> "delete", "rigth" -> "right",
// "motorcyle" -> "motorcycle"), in place. Domain words: words.json, vehicles.json, colours and
// nouns. A word of the English word lists (/usr/share/dict, $CHATSIM_WORDLIST) is never changed,
// nor one with two equally near domain words; without a word list nothing is changed.
// Words in `names` (said with a capital inside a sentence: "a Lada Niva") are names, never typos.
void correct_typos(std::vector<std::string>& words, const std::set<std::string>& names = {});

// Loads the vocabulary and word lists now (an agent starting), so that its first command does not
// wait for them (about 30 ms). Throws std::runtime_error when a vocabulary file is missing or broken.
void load_vocabulary();
// Whether the interpreter knows the word (words.json, the vehicle vocabulary, colours, nouns),
// and whether it is English at all (the word lists; false without them).
bool is_domain_word(const std::string& w);
bool is_english_word(const std::string& w);

// "a black zorblax", "a vinfast vf8": where a vehicle belongs (from `from`, past articles, numbers,
// colours and a few adjectives), a name that is neither English nor known: a vehicle of unknown
// make. The name's words [begin, end); none without a word list (every word would be unknown).
std::optional<std::pair<size_t, size_t>> unknown_vehicle_name(const std::vector<std::string>& w, size_t from);

}  // namespace chatsim::agents::lexicon
