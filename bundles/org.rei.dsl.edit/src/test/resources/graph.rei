// An explicit floor graph: four floors in a row, a wall on top of the second.
testcase Graph {
	room Corridor {
		floor A right B // the entrance
		floor B left A top W1

		/* the far end */
		floor C left B right D
		floor D
		wall W1
		// the chair stays
		object chair : Chair on C
		robot tb3 : Waffle on A
	}
	mission Across {
		goto B
		goto A
	}
}
