// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.editor;

import java.io.IOException;
import java.io.InputStream;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.core.runtime.Platform;
import org.rei.eclipse.ReiIds;
import org.rei.eclipse.ReiPlugin;

/**
 * The keywords of a language, read from its Xtext grammar, which the build copies into the plug-in: the grammar
 * stays the one source, and a keyword added to it is coloured without a second list to update.
 */
final class Keywords {
	/** A quoted word in a grammar rule ('floor', 'robot'); punctuation keywords are not coloured. */
	private static final Pattern QUOTED_WORD = Pattern.compile("'([A-Za-z_][A-Za-z0-9_]*)'");

	private Keywords() {
	}

	static Set<String> of(String grammar) {
		Set<String> words = new TreeSet<>();
		URL entry = Platform.getBundle(ReiIds.PLUGIN).getEntry("generated/grammars/" + grammar);
		if (entry == null) {
			ReiPlugin.log("the REI plug-in has no grammar " + grammar + ": keywords are not coloured", null);
			return words;
		}
		try (InputStream in = entry.openStream()) {
			Matcher matcher = QUOTED_WORD.matcher(new String(in.readAllBytes(), StandardCharsets.UTF_8));
			while (matcher.find()) {
				words.add(matcher.group(1));
			}
		} catch (IOException unreadable) {
			ReiPlugin.log("cannot read the grammar " + grammar, unreadable);
		}
		return words;
	}
}
