// A falsification benchmark room (docs/search.md, Benchmark): the robot drives a corridor one floor wide from
// its west end to its east end (about 31 s), and two people's lanes cross it through doorways, one near the
// start (the robot passes it at about 8 s) and one past the middle (about 23 s). In this base case both people
// set off long after the robot has arrived. The search spec lets each person set off anywhere in a minute at a
// wide range of speeds: only a few seconds of each range bring a person into the corridor as the robot passes,
// so failures are rare under random sampling, and they come in several kinds (either person, on several tiles).
testcase Doorways {
  room Corridor map "
    ###.###.###
    #.........#
    ###.###.###
  " {
    human early trajectory [F_2_0 @ 90s, F_2_2 @ 93s]
    human late trajectory [F_6_2 @ 90s, F_6_0 @ 93s]
    robot tb3 : Waffle on F_0_1
  }
  mission Through {
    goto F_4_1
    goto F_8_1
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
