/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.scoping;

import java.nio.file.Path;
import java.util.Optional;
import java.util.stream.Collectors;
import java.util.stream.StreamSupport;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.xtext.diagnostics.Diagnostic;
import org.eclipse.xtext.diagnostics.DiagnosticMessage;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.linking.impl.LinkingDiagnosticMessageProvider;
import org.eclipse.xtext.scoping.IScope;
import org.rei.catalogue.CataloguePackage;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.OccupancyLayout;
import org.rei.context.TestCase;
import org.rei.context.layout.Cell;
import org.rei.context.layout.MapFiles;
import org.rei.dsl.derived.RoomDesugaring;
import org.rei.maps.FloorBlocks;
import org.eclipse.xtext.EcoreUtil2;

import com.google.inject.Inject;

import org.eclipse.xtext.scoping.IScopeProvider;

/** Says what kind of name was expected where a reference does not resolve, and lists candidates when few. */
public class ReiLinkingDiagnosticMessageProvider extends LinkingDiagnosticMessageProvider {

	private static final int MAX_LISTED = 8;

	/** A map room's floor is missing because its map is unusable: the map's error is the one to read. */
	private static final String SAID_ON_THE_MAP = "";

	@Inject
	private IScopeProvider scopeProvider;

	@Override
	public DiagnosticMessage getUnresolvedProxyMessage(ILinkingDiagnosticContext context) {
		EClass target = context.getReference().getEReferenceType();
		String onMap = mapBlockMessage(context);
		if (SAID_ON_THE_MAP.equals(onMap)) {
			return null; // no diagnostic: the map's own error says why the room has no such floor
		}
		if (onMap != null) {
			return new DiagnosticMessage(onMap, Severity.ERROR, Diagnostic.LINKING_DIAGNOSTIC);
		}
		String what = describe(target);
		String message = "Unknown " + what + " '" + context.getLinkText() + "': expected the name of "
				+ article(what) + " " + what + candidates(context);
		return new DiagnosticMessage(message, Severity.ERROR, Diagnostic.LINKING_DIAGNOSTIC);
	}

	/**
	 * In a room from an occupancy map, a name {@code F_x_y} that is no floor names a block of the map that is not
	 * free, or none: say which, and why, instead of listing floors ({@link #SAID_ON_THE_MAP} when the map itself
	 * is unusable: unreadable, a floor size that is not positive, or too many floors).
	 */
	private static String mapBlockMessage(ILinkingDiagnosticContext context) {
		EClass target = context.getReference().getEReferenceType();
		if (target != ContextPackage.Literals.FLOOR && target != ContextPackage.Literals.BUILDING_BLOCK) {
			return null;
		}
		TestCase testCase = EcoreUtil2.getContainerOfType(context.getContext(), TestCase.class);
		Environment environment = testCase == null ? null : testCase.getOwnedEnvironment();
		if (environment == null || !(environment.getOwnedLayout() instanceof OccupancyLayout layout)) {
			return null;
		}
		Optional<Cell> block = MapFiles.blockOf(context.getLinkText());
		if (block.isEmpty()) {
			return null;
		}
		Optional<FloorBlocks> blocks = RoomDesugaring.freeBlocks(layout);
		if (blocks.isEmpty() || blocks.get().freeCount() > RoomDesugaring.MAX_MAP_FLOORS) {
			return SAID_ON_THE_MAP;
		}
		int x = block.get().x();
		int y = block.get().y();
		FloorBlocks map = blocks.get();
		String file = Path.of(layout.getMap()).getFileName().toString();
		if (!map.contains(x, y)) {
			return context.getLinkText() + " is not a floor of " + file + ": the map has " + map.columns() + " x "
					+ map.rows() + " blocks of " + RoomDesugaring.metres(map.floorSize()) + " m (F_0_0 to F_"
					+ (map.columns() - 1) + "_" + (map.rows() - 1) + ")";
		}
		if (map.isFree(x, y)) {
			return null; // cannot be: a free block is a floor
		}
		return context.getLinkText() + " is not a free floor of " + file + ": " + map.obstacleCells(x, y) + " of its "
				+ map.cells(x, y) + " cells are obstacles" + (layout.isUnknownFree() ? "" : " (occupied or unknown)");
	}

	private String candidates(ILinkingDiagnosticContext context) {
		IScope scope = scopeProvider.getScope(context.getContext(), context.getReference());
		var names = StreamSupport.stream(scope.getAllElements().spliterator(), false)
				.map(d -> d.getName().toString()).limit(MAX_LISTED + 1L).toList();
		if (names.isEmpty()) {
			return "";
		}
		String listed = names.stream().limit(MAX_LISTED).collect(Collectors.joining(", "));
		return " (" + listed + (names.size() > MAX_LISTED ? ", ..." : "") + ")";
	}

	private static String describe(EClass target) {
		if (target == ContextPackage.Literals.FLOOR) {
			return "floor";
		}
		if (target == ContextPackage.Literals.BUILDING_BLOCK) {
			return "floor or wall";
		}
		if (target == CataloguePackage.Literals.OBJECT_TYPE) {
			return "object type";
		}
		return target.getName();
	}

	private static String article(String noun) {
		return "aeiou".indexOf(noun.charAt(0)) >= 0 ? "an" : "a";
	}
}
