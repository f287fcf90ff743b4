// POV-Ray .ini files: the options drt reads from them (keys are
// case-insensitive; `;` starts a comment; `[section]` lines are skipped):
//   Input_File_Name / +I     the scene (relative to the .ini's folder)
//   Output_File_Name / +O    the image, or a frame pattern (animation.h frameFileName)
//   Width / +W, Height / +H  the image size
//   Initial_Frame / +KFI, Final_Frame / +KFF, Initial_Clock / +KI, Final_Clock / +KF,
//   Subset_Start_Frame / +SF, Subset_End_Frame / +EF (frame numbers, or fractions
//   of the range when between 0 and 1 with a decimal point), Cyclic_Animation / +KC,
//   Clock / +K               the animation (animation.h), or one clock value
//   Library_Path / +L        folders #include searches (several allowed)
// Other keys are POV-Ray's rendering options drt has no use for: they are
// reported as warnings and ignored.
#pragma once

#include "animation/animation.h"
#include "core/diagnostics.h"

#include <optional>
#include <string>
#include <vector>

namespace drt {

struct IniSettings {
    std::optional<std::string> input;
    std::optional<std::string> output;
    std::optional<int> width, height;
    std::optional<int> initialFrame, finalFrame;
    std::optional<double> initialClock, finalClock;
    std::optional<double> subsetStart, subsetEnd; // frames, or fractions (resolved by applyIni)
    bool subsetStartFraction = false, subsetEndFraction = false;
    std::optional<bool> cyclic;
    std::optional<double> clock;
    std::vector<std::string> libraryPaths;
};

// Reads an .ini file; errors (unreadable file, bad values) go to `diagnostics`
// with their line and column.
std::optional<IniSettings> readIniFile(const std::string& path, Diagnostics& diagnostics);
std::optional<IniSettings> readIniText(const std::string& text, const std::string& name, Diagnostics& diagnostics,
                                       const std::string& baseDir = ".");

// The animation the settings describe, over `base` (what the command line
// left unset). True if any animation key was given.
bool applyIni(const IniSettings& ini, Animation& animation);

} // namespace drt
