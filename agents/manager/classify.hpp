#pragma once
// What one clause of a command is (classify.cpp), and the words of references (references.cpp):
// used inside the manager only.
#include <optional>
#include <string>
#include <vector>

#include "agents/manager/decompose.hpp"

namespace chatsim::agents::manager::detail {

// Verbs that start an addition ("add", "put", "park" ...) or a deletion ("remove", "get" ...).
const std::vector<std::string>& add_verbs();
const std::vector<std::string>& delete_verbs();

// A vehicle noun or make among the words (not a cone, barrier or pedestrian).
bool mentions_vehicle(const std::vector<std::string>& words);
// An amount in a unit of length (text::length_units: "2 m", "three car lengths") or, with
// `angles`, in degrees.
bool says_amount(const std::vector<std::string>& words, bool angles = true);

// "have a tahoe come from the right" -> "add a tahoe come from the right"; other clauses unchanged
// (said_as_addition.cpp).
std::vector<std::string> causative_addition(const std::vector<std::string>& clause);
// "add a motorbike behind the one that's already there" -> "... behind the motorbike"; other
// clauses unchanged.
std::vector<std::string> existing_one(const std::vector<std::string>& clause);
// "fill the bays", "line the street with parked cars" -> "add a row of parked cars in ..."; other
// clauses unchanged.
std::vector<std::string> fill_addition(const std::vector<std::string>& clause);

// "no, dark green", "red instead": a colour said with filler words only, as its words ("dark
// green"); none for any other clause (bare_clauses.cpp).
std::optional<std::string> bare_color(const std::vector<std::string>& clause);
// "slower", "a bit closer", "no, faster": a change of speed or distance said alone, as its words
// (without "no" or "please"); none for any other clause.
std::optional<std::string> bare_change(const std::vector<std::string>& clause);
// "in front of the bendy bus", "no, behind it", "in the bus lane": a place said alone, no verb, as
// its words (without "no"); none for any other clause.
std::optional<std::string> bare_place(const std::vector<std::string>& clause);
// "empty the drive-thru", "clear out the lay-by", "clear the queue at the barrier": every vehicle
// there goes, as the deletion to make ("remove all vehicles in the drive thru"); none for a clause
// that names a vehicle or is not such a command.
std::optional<std::string> cleared_place(const std::vector<std::string>& clause);
// "sorry, I meant a Kia Sorento", "I meant behind it": a correction of what was added, as the
// revision to make ("make it a kia sorento", "put it behind it"); none for any other clause.
std::optional<std::string> meant_correction(const std::vector<std::string>& clause);

// "move it behind the van" -> "move behind the van": the words naming the revised vehicle go
// (references.cpp).
std::string strip_reference(const std::string& text, const std::string& reference);
// "put it behind it", "no, in front of it": an "it" after a place word cannot be the vehicle being
// moved; it is the other one, the vehicle that placed it, said as kOtherVehicle.
inline constexpr const char* kOtherVehicle = "the other vehicle";
std::string anchor_as_other(const std::string& text);

// The instruction one clause (its words, lower case, typos corrected) asks for.
Instruction classify(const std::vector<std::string>& clause);

}  // namespace chatsim::agents::manager::detail
