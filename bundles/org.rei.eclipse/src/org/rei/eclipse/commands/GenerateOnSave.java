// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.commands;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IResourceChangeEvent;
import org.eclipse.core.resources.IResourceChangeListener;
import org.eclipse.core.resources.IResourceDelta;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.core.runtime.preferences.InstanceScope;
import org.rei.eclipse.ReiIds;
import org.rei.eclipse.ReiPlugin;

/** With the preference on, a saved .rei file has its artifacts generated again (thesis 7.3: "by saving"). */
public final class GenerateOnSave implements IResourceChangeListener {
	private GenerateOnSave() {
	}

	public static GenerateOnSave install() {
		GenerateOnSave listener = new GenerateOnSave();
		ResourcesPlugin.getWorkspace().addResourceChangeListener(listener, IResourceChangeEvent.POST_CHANGE);
		return listener;
	}

	public void uninstall() {
		ResourcesPlugin.getWorkspace().removeResourceChangeListener(this);
	}

	@Override
	public void resourceChanged(IResourceChangeEvent event) {
		if (!InstanceScope.INSTANCE.getNode(ReiIds.PLUGIN).getBoolean(ReiIds.PREF_GENERATE_ON_SAVE, false)) {
			return;
		}
		List<IFile> saved = new ArrayList<>();
		try {
			event.getDelta().accept(delta -> {
				if (delta.getResource().getType() == IResource.FILE && delta.getKind() == IResourceDelta.CHANGED
						&& (delta.getFlags() & IResourceDelta.CONTENT) != 0
						&& delta.getResource().getName().endsWith(".rei")) {
					saved.add((IFile) delta.getResource());
				}
				return true;
			});
		} catch (CoreException failed) {
			ReiPlugin.log("generate on save: cannot read the workspace's changes", failed);
		}
		saved.forEach(file -> new GenerateJob(file).schedule());
	}
}
