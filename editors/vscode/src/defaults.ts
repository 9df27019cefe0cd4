// SPDX-License-Identifier: EPL-2.0
// The settings' defaults, also declared in package.json; a test checks that the two agree.

export const DEFAULTS = {
  "rei.java.home": "",
  "rei.server.jar": "",
  // Under out/ beside the sources: one folder per test case that neither clutters the folder of the .rei files
  // nor mixes with a run's output (REI's own checkout ignores out/).
  "rei.generate.outputDirectory": "${workspaceFolder}/out/${fileBasenameNoExtension}-artifacts",
  "rei.generate.onSave": false,
  "rei.launcher": "rei",
  "rei.run.outputDirectory": "${workspaceFolder}/out/${fileBasenameNoExtension}",
} as const;
