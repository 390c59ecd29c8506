// Legacy header of manual §10.4.11: the interface objects of the 2009
// engine under their original names, so that the manual's code compiles
// unchanged (crisp_data, crisp_data_list, command, command_list,
// destroy_object). New code uses mrt_brian/types.h.
#pragma once

#include <algorithm>

#include "mrt_brian/legacy.h"

using mrt::brian::legacy::command;
using mrt::brian::legacy::command_list;
using mrt::brian::legacy::crisp_data;
using mrt::brian::legacy::crisp_data_list;
using mrt::brian::legacy::destroy_object;
