/*
 * Copyright (c) 2026 the REI authors.
 * SPDX-License-Identifier: EPL-2.0
 */
package org.rei.dsl.validation;

import java.util.List;

import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.rei.context.AsciiLayout;
import org.rei.context.BuildingBlock;
import org.rei.context.ContextPackage;
import org.rei.context.Environment;
import org.rei.context.GridLayout;
import org.rei.context.layout.FloorLayout;
import org.rei.context.layout.LayoutProblem;
import org.rei.dsl.derived.DerivedMarker;
import org.rei.dsl.derived.RoomDesugaring;

/**
 * The room as a whole: a robot in it, a consistent floor graph that maps to coordinates (thesis 6.2.1), walls
 * that border a floor (thesis 4.1.2), and sane sizes.
 */
public class RoomValidator extends ReiCheckBase {

	@Check
	public void checkRobotPresent(Environment environment) {
		if (environment.getOwnedRobot() == null) {
			error("Room '" + environment.getName() + "' has no robot: expected a line like 'robot tb3 : Waffle on F_0_0'",
					environment, ContextPackage.Literals.NAMED_ELEMENT__NAME, ReiIssueCodes.MISSING_ROBOT);
		}
	}

	/** The grammar lets the robot stand anywhere in the room; a second one would silently replace the first. */
	@Check
	public void checkSingleRobot(Environment environment) {
		List<INode> robots = NodeModelUtils.findNodesForFeature(environment,
				ContextPackage.Literals.ENVIRONMENT__OWNED_ROBOT);
		for (INode extra : robots.subList(Math.min(1, robots.size()), robots.size())) {
			acceptError("Room '" + environment.getName() + "' already has a robot on line "
					+ robots.get(0).getStartLine() + ": expected one robot per test case", environment,
					extra.getOffset(), extra.getLength(), ReiIssueCodes.MULTIPLE_ROBOTS);
		}
	}

	@Check
	public void checkFloorSize(Environment environment) {
		if (!(environment.getFloorSize() > 0)) {
			error("Floor size must be positive, in metres", environment,
					ContextPackage.Literals.ENVIRONMENT__FLOOR_SIZE, ReiIssueCodes.NON_POSITIVE);
		}
	}

	@Check
	public void checkGridSize(GridLayout grid) {
		if (grid.getColumns() < 1 || grid.getRows() < 1) {
			error("A room needs at least 1 x 1 floors", grid, ContextPackage.Literals.GRID_LAYOUT__COLUMNS,
					ReiIssueCodes.NON_POSITIVE);
		} else if (RoomDesugaring.tooLarge(grid)) {
			error("A room may have at most " + RoomDesugaring.MAX_CELLS + " floors, this one has "
					+ (long) grid.getColumns() * grid.getRows(), grid, ContextPackage.Literals.GRID_LAYOUT__COLUMNS,
					ReiIssueCodes.ROOM_TOO_LARGE);
		}
	}

	@Check
	public void checkMapHasFloors(AsciiLayout ascii) {
		if (RoomDesugaring.tooLarge(ascii)) {
			error("A map may span at most " + RoomDesugaring.MAX_CELLS + " cells (lines x longest line)", ascii,
					ContextPackage.Literals.ASCII_LAYOUT__MAP, ReiIssueCodes.ROOM_TOO_LARGE);
			return;
		}
		if (ascii.eContainer() instanceof Environment environment
				&& environment.getOwnedBlocks().stream().noneMatch(DerivedMarker::isDerived)) {
			error("The map draws no floor: expected lines of '.' (floor) and '#' (wall)", ascii,
					ContextPackage.Literals.ASCII_LAYOUT__MAP, ReiIssueCodes.EMPTY_LAYOUT);
		}
	}

	@Check
	public void checkNoExplicitBlocksWithLayout(Environment environment) {
		if (environment.getOwnedLayout() == null) {
			return;
		}
		for (BuildingBlock block : environment.getOwnedBlocks()) {
			if (!DerivedMarker.isDerived(block)) {
				error("Room '" + environment.getName() + "' derives its floors and walls from its size or map: "
						+ "declare floors and walls only in a room without one", block,
						ContextPackage.Literals.NAMED_ELEMENT__NAME, ReiIssueCodes.BLOCKS_WITH_LAYOUT);
			}
		}
	}

	@Check
	public void checkFloorGraphMapsToCoordinates(Environment environment) {
		if (environment.getOwnedBlocks().isEmpty()) {
			return;
		}
		for (LayoutProblem problem : FloorLayout.compute(environment).problems()) {
			errorAt(problem.element(), problem.feature() != null ? problem.feature()
					: ContextPackage.Literals.NAMED_ELEMENT__NAME, problem.message(), problem.code());
		}
	}
}
