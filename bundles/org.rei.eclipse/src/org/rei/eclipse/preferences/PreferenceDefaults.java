// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.preferences;

import org.eclipse.core.runtime.preferences.AbstractPreferenceInitializer;
import org.eclipse.core.runtime.preferences.DefaultScope;
import org.eclipse.core.runtime.preferences.IEclipsePreferences;
import org.rei.eclipse.ReiIds;
import org.rei.eclipse.commands.Generator;

public final class PreferenceDefaults extends AbstractPreferenceInitializer {
	@Override
	public void initializeDefaultPreferences() {
		IEclipsePreferences defaults = DefaultScope.INSTANCE.getNode(ReiIds.PLUGIN);
		defaults.put(ReiIds.PREF_OUTPUT_FOLDER, Generator.DEFAULT_OUTPUT);
		defaults.putBoolean(ReiIds.PREF_GENERATE_ON_SAVE, false);
		defaults.put(ReiIds.PREF_LAUNCHER, "");
		defaults.put(ReiIds.PREF_JAVA, "");
		defaults.putBoolean(ReiIds.PREF_OPEN_REPORT, true);
	}
}
