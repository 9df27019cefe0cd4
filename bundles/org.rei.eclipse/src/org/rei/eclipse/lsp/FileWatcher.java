// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.lsp;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.IResourceChangeEvent;
import org.eclipse.core.resources.IResourceChangeListener;
import org.eclipse.core.resources.IResourceDelta;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.lsp4j.FileChangeType;
import org.eclipse.lsp4j.FileEvent;
import org.rei.eclipse.ReiPlugin;

/**
 * Tells a running server about .rei and .vepl files created, changed or deleted outside its editors (a pull, a
 * copy, a catalogue edited elsewhere), so the markers of every file stay true.
 */
public final class FileWatcher implements IResourceChangeListener {
	private final LanguageServerConnection server;

	private FileWatcher(LanguageServerConnection server) {
		this.server = server;
	}

	public static FileWatcher install(LanguageServerConnection server) {
		FileWatcher watcher = new FileWatcher(server);
		ResourcesPlugin.getWorkspace().addResourceChangeListener(watcher, IResourceChangeEvent.POST_CHANGE);
		return watcher;
	}

	public void uninstall() {
		ResourcesPlugin.getWorkspace().removeResourceChangeListener(this);
	}

	@Override
	public void resourceChanged(IResourceChangeEvent event) {
		List<FileEvent> events = new ArrayList<>();
		try {
			event.getDelta().accept(delta -> {
				IResource resource = delta.getResource();
				if (resource.getType() == IResource.FILE && Documents.isReiSource(resource.getName())
						&& resource.getLocation() != null) {
					FileChangeType type = switch (delta.getKind()) {
					case IResourceDelta.ADDED -> FileChangeType.Created;
					case IResourceDelta.REMOVED -> FileChangeType.Deleted;
					default -> (delta.getFlags() & IResourceDelta.CONTENT) != 0 ? FileChangeType.Changed : null;
					};
					if (type != null) {
						events.add(new FileEvent(Documents.uriOf(resource.getLocation().toFile().toPath()), type));
					}
				}
				return true;
			});
		} catch (CoreException failed) {
			ReiPlugin.log("cannot read the workspace's changes", failed);
		}
		server.filesChanged(events);
	}
}
