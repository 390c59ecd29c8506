// Legacy DCDT names (manual chapter 3), so member code written for the
// original toolkit compiles unchanged: DCDT_Agora, DCDT_Member, DCDT_Msg,
// DCDT_RequestType, DCDT_LOCAL_MSG / DCDT_REMOTE_MSG / DCDT_ALL_MSG,
// DCDT_TIME, the delivery warranties and the MRT message type numbers.
#pragma once

#include "mrt_dcdt_bridge/agora.h"
#include "mrt_dcdt_bridge/member.h"
#include "mrt_dcdt_bridge/msg.h"
#include "mrt_dcdt_bridge/types.h"

using DCDT_Agora = mrt::dcdt::Agora;
using DCDT_Member = mrt::dcdt::Member;
using DCDT_Msg = mrt::dcdt::Msg;
using DCDT_RequestType = mrt::dcdt::RequestType;
using DCDT_TIME = mrt::dcdt::DCDT_TIME;
using mrt::dcdt::DCDT_ALL_MSG;
using mrt::dcdt::DCDT_LOCAL_MSG;
using mrt::dcdt::DCDT_REMOTE_MSG;
using mrt::dcdt::DCDT_DW_GUARANTEED;
using mrt::dcdt::DCDT_DW_NONE;
using mrt::dcdt::DCDT_DW_RETRANSMIT;
using mrt::dcdt::MSG_FROM_ANCHORER;
using mrt::dcdt::MSG_FROM_BRIAN;
using mrt::dcdt::MSG_FROM_JOYPAD_BRIEF;
using mrt::dcdt::MSG_FROM_MAP;
using mrt::dcdt::MSG_FROM_MONITOR;
using mrt::dcdt::MSG_FROM_MOTION;
using mrt::dcdt::MSG_FROM_REFBOX;
using mrt::dcdt::MSG_FROM_SCARE;
using mrt::dcdt::MSG_FROM_SONAR_QUALITY;
using mrt::dcdt::MSG_FROM_VISION;
using mrt::dcdt::MSG_FROM_VISION_FRONTAL;
using mrt::dcdt::MSG_FROM_VISION_OMNIDIR;
using mrt::dcdt::MSG_TO_ANCHORER;
using mrt::dcdt::MSG_TO_BRIAN;
using mrt::dcdt::MSG_TO_MOTION;
