// SPDX-License-Identifier: EPL-2.0
package org.rei.eclipse.tests;

import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IProject;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.resources.ResourcesPlugin;
import org.eclipse.core.runtime.CoreException;
import org.eclipse.jface.text.IDocument;
import org.eclipse.jface.text.ITextOperationTarget;
import org.eclipse.jface.text.ITextViewer;
import org.eclipse.swt.SWT;
import org.eclipse.swt.graphics.GC;
import org.eclipse.swt.graphics.Image;
import org.eclipse.swt.graphics.ImageData;
import org.eclipse.swt.graphics.ImageLoader;
import org.eclipse.swt.graphics.Rectangle;
import org.eclipse.swt.widgets.Display;
import org.eclipse.swt.widgets.Shell;
import org.eclipse.ui.IWorkbenchPage;
import org.eclipse.ui.PlatformUI;
import org.eclipse.ui.texteditor.ITextEditor;
import org.rei.eclipse.ReiIds;

/** The workbench as the tests use it: files, editors, markers, and waiting while the UI keeps running. */
final class Workbench {
	private Workbench() {
	}

	static IProject project(String name) throws CoreException {
		IProject project = ResourcesPlugin.getWorkspace().getRoot().getProject(name);
		if (!project.exists()) {
			project.create(null);
		}
		project.open(null);
		return project;
	}

	static IFile write(IProject project, String name, String text) throws CoreException {
		return write(project, name, text.getBytes(StandardCharsets.UTF_8));
	}

	static IFile write(IProject project, String name, byte[] bytes) throws CoreException {
		IFile file = project.getFile(name);
		ByteArrayInputStream contents = new ByteArrayInputStream(bytes);
		if (file.exists()) {
			file.setContents(contents, IResource.FORCE, null);
		} else {
			file.create(contents, IResource.FORCE, null);
		}
		return file;
	}

	static IWorkbenchPage page() {
		return PlatformUI.getWorkbench().getActiveWorkbenchWindow().getActivePage();
	}

	static IDocument documentOf(ITextEditor editor) {
		return editor.getDocumentProvider().getDocument(editor.getEditorInput());
	}

	static ITextViewer viewerOf(ITextEditor editor) {
		return (ITextViewer) editor.getAdapter(ITextOperationTarget.class);
	}

	static List<IMarker> markers(IFile file) {
		try {
			return Arrays.asList(file.findMarkers(ReiIds.PROBLEM_MARKER, true, IResource.DEPTH_ZERO));
		} catch (CoreException gone) {
			return List.of();
		}
	}

	static String describe(List<IMarker> markers) {
		return markers.stream().map(marker -> marker.getAttribute(IMarker.LINE_NUMBER, -1) + ": "
				+ marker.getAttribute(IMarker.MESSAGE, "")).toList().toString();
	}

	/** Runs the event loop until the condition holds; fails with the description after the timeout. */
	static void waitUntil(BooleanSupplier condition, long timeoutMillis, Supplier<String> description) {
		Display display = Display.getCurrent();
		long deadline = System.currentTimeMillis() + timeoutMillis;
		while (!condition.getAsBoolean()) {
			if (System.currentTimeMillis() > deadline) {
				fail("not within " + timeoutMillis + " ms: " + description.get());
			}
			if (!display.readAndDispatch()) {
				display.timerExec(50, () -> {
				}); // wakes the sleep below: markers come from other threads, not as UI events
				display.sleep();
			}
		}
	}

	/** Lets queued UI work run (editor set-up, jobs' UI parts). */
	static void flush(long millis) {
		waitUntil(new BooleanSupplier() {
			final long end = System.currentTimeMillis() + millis;

			@Override
			public boolean getAsBoolean() {
				return System.currentTimeMillis() >= end;
			}
		}, millis + 1000, () -> "");
	}

	/** A PNG of the workbench window, for the README (only when the build asks for screenshots). */
	static void screenshot(String name) throws IOException {
		String folder = System.getProperty("rei.screenshots");
		if (folder == null) {
			return;
		}
		Path target = Files.createDirectories(Path.of(folder)).resolve(name);
		Display display = Display.getCurrent();
		Shell shell = PlatformUI.getWorkbench().getActiveWorkbenchWindow().getShell();
		Rectangle bounds = shell.getBounds();
		Image image = new Image(display, bounds.width, bounds.height);
		GC gc = new GC(display);
		try {
			gc.copyArea(image, bounds.x, bounds.y);
			ImageLoader loader = new ImageLoader();
			loader.data = new ImageData[] { image.getImageData() };
			loader.save(target.toString(), SWT.IMAGE_PNG);
		} finally {
			gc.dispose();
			image.dispose();
		}
	}
}
