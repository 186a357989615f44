#pragma once
// What one clause of a command is (classify.cpp): used by the decomposition only.
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
// "fill the bays", "line the street with parked cars" -> "add a row of parked cars in ..."; other
// clauses unchanged.
std::vector<std::string> fill_addition(const std::vector<std::string>& clause);

// The instruction one clause (its words, lower case, typos corrected) asks for.
Instruction classify(const std::vector<std::string>& clause);

}  // namespace chatsim::agents::manager::detail
