// Included by preprocessor.fx, relative to it.
#pragma once
#define FROM_INCLUDE 42
