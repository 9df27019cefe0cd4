// A falsification benchmark room (docs/search.md, Benchmark) where failures are rare under random sampling and
// come in many kinds: the robot drives a corridor one floor wide, 17 floors long, from its west end to its east
// end (62 simulated seconds), and four people's lanes cross it, each lane 5 floors either side of the corridor, at
// x = 2, 6, 10 and 14 (the robot passes them at about 8, 23, 39 and 54 s). In this base case every person sets
// off long after the robot has arrived. The search spec lets each person set off anywhere in 15 minutes at a
// wide range of speeds: a person meets the robot only if they reach the corridor within a second or two of the
// robot's passage, but while a person walks their long lane as the robot passes, the robot's clearance to them
// falls smoothly as their arrival approaches the passage, which gives a search its slope.
testcase Crossings {
  room Corridor map "
    ###.###.###.###.###
    ###.###.###.###.###
    ###.###.###.###.###
    ###.###.###.###.###
    ###.###.###.###.###
    #.................#
    ###.###.###.###.###
    ###.###.###.###.###
    ###.###.###.###.###
    ###.###.###.###.###
    ###.###.###.###.###
  " {
    human north2 trajectory [F_2_10 @ 1000s, F_2_0 @ 1010s]
    human south6 trajectory [F_6_0 @ 1000s, F_6_10 @ 1010s]
    human north10 trajectory [F_10_10 @ 1000s, F_10_0 @ 1010s]
    human south14 trajectory [F_14_0 @ 1000s, F_14_10 @ 1010s]
    robot tb3 : Waffle on F_0_5
  }
  mission Through {
    goto F_8_5
    goto F_16_5
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
