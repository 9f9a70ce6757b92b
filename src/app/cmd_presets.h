#pragma once
// `marble presets`: one line per built-in preset: its name and a one-line description.
namespace marble {
int runPresetsCommand();
}
