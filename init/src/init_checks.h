#pragma once
// `init`'s input checks (issue 44 item 5), apart from the config writer: every option a user
// gives is checked and named before anything is written, and a key of the written config that
// the config reader refuses is named by the option that set it, not by a file never written.
#include <string>

#include "modaltyre/core/errors.h"
#include "modaltyre/init/init_tyre.h"
#include "modaltyre/init/tyre_size.h"

namespace modaltyre::init {

/// Refuses (InputError at the option) what no config can be made of: a name with control
/// characters (it would end the header comment and write keys of its own) or bytes that are not
/// UTF-8; a pressure, mass, width, depth or load that is given but not a finite number > 0 (or
/// outside its range: a belt or tread wider than the section, a tread as deep as the section is
/// high); the modal data as both or neither of a list and a hammer file, or a list's orders and
/// damping with a hammer file (the file's own shapes and columns give them).
void check_init_inputs(const InitInputs& in, const TyreSize& size);

/// The option of `init` that sets a key of the written config ("modal.belt_width_mm" ->
/// "--belt-width-mm"); "" for a key no single option sets.
std::string option_of_key(const std::string& key);

/// `e`, raised by the config reader on the text init wrote, as an InputError at the option that
/// set the key (the reader's range and message kept), or at `init` with the key when no one
/// option sets it.
[[noreturn]] void rethrow_at_option(const InputError& e);

/// Refuses (InputError at --frequencies or --hammer) a ring whose mass per length no tyre has:
/// frequencies in the wrong unit or of another structure make a ring of tonnes per metre.
void check_ring_mass(double mass_per_length_kg_m, double outer_radius_m, bool from_list);

}  // namespace modaltyre::init
