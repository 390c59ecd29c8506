// Legacy header of manual §10.4.11: the `Brian` class under its original
// name (the eight-file constructor, plus one with the predicate-actions
// file; `command_list* run(crisp_data_list*)`). The user's `Parser` and
// `Messenger` stay the user's: mrt::brian::legacy::DataSource and
// CommandSink are interfaces they may implement. New code uses
// mrt_brian/brian.h (mrt::brian::Brian).
#pragma once

#include "interf_obj.h"

using Brian = mrt::brian::legacy::Brian;
