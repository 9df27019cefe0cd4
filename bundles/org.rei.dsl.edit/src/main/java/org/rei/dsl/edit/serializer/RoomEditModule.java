/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.edit.serializer;

import org.eclipse.xtext.formatting2.IFormatter2;
import org.eclipse.xtext.ide.serializer.IChangeSerializer;
import org.eclipse.xtext.ide.serializer.hooks.IEObjectDescriptionProvider;
import org.eclipse.xtext.ide.serializer.impl.ChangeSerializer;
import org.eclipse.xtext.ide.serializer.impl.PartialSerializer;
import org.eclipse.xtext.service.AbstractGenericModule;
import org.eclipse.xtext.serializer.sequencer.ITransientValueService;

import com.google.inject.Binder;

/**
 * What the change serializer needs beyond the language's runtime bindings, mixed into {@link
 * org.rei.dsl.ReiRuntimeModule} for the editor's resources only: the language server and the command line keep
 * theirs untouched.
 */
public class RoomEditModule extends AbstractGenericModule {

	public Class<? extends IChangeSerializer> bindIChangeSerializer() {
		return ChangeSerializer.class;
	}

	public Class<? extends PartialSerializer> bindPartialSerializer() {
		return RoomPartialSerializer.class;
	}

	/** The language has no formatter; without one, written statements would run on without spaces or lines. */
	public Class<? extends IFormatter2> bindIFormatter2() {
		return RoomLayoutFormatter.class;
	}

	public Class<? extends IEObjectDescriptionProvider> bindIEObjectDescriptionProvider() {
		return NoNameIndex.class;
	}

	/** Floors and walls derived from a grid or a map are never written back as text. */
	public void configureTransientValues(Binder binder) {
		binder.bind(ITransientValueService.class).to(DerivedBlocksTransient.class);
	}
}
