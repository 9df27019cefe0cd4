// SPDX-License-Identifier: EPL-2.0
//
// A small external system under test written with REI's Java kit (docs/sut.md): turn towards the goal, drive,
// slow down and steer away from whatever the laser sees close ahead (a person crossing). Run it as
//
//   ./rei run examples/simple_navigation.rei -o out \
//       --sut "java -cp sut-kits/java/target/rei-sut-kit.jar examples/sut/java/GoToGoalSut.java"
//
// It knows only what a real robot would: wheel odometry (in world coordinates: the mission's start pose at
// tick 0, so it is comparable with goal poses) and the laser. No map, no planner: a room with furniture in the way needs more.

import java.util.Locale;

import org.rei.sut.kit.Command;
import org.rei.sut.kit.Goal;
import org.rei.sut.kit.Pose;
import org.rei.sut.kit.Scan;
import org.rei.sut.kit.Session;
import org.rei.sut.kit.SutClient;
import org.rei.sut.kit.SystemUnderTest;
import org.rei.sut.kit.Tick;

public class GoToGoalSut implements SystemUnderTest {

	static final double FRONT = Math.toRadians(30); // half-width of the sector watched for obstacles
	static final double STOP_AT = 0.35; // m from the laser: stand still
	static final double SLOW_FROM = 0.7; // m: slow down linearly between here and STOP_AT
	static final double AVOID_TURN = 0.8; // rad/s away from an obstacle at STOP_AT
	static final double GIVE_UP_AFTER = 60; // s without getting 5 cm closer

	private Session.Robot robot;
	private double best;
	private double bestT;

	public static void main(String[] args) {
		SutClient.runAndExit(new GoToGoalSut());
	}

	@Override
	public void onStart(Session session) {
		robot = session.robot();
	}

	@Override
	public void onGoal(Goal goal) {
		best = Double.POSITIVE_INFINITY;
		bestT = goal.t();
	}

	@Override
	public Command onTick(Tick tick) {
		Goal goal = tick.goal();
		if (goal == null || !goal.isActive()) {
			return Command.STOP;
		}
		Pose odom = tick.odom();
		double distance = odom.distanceTo(goal.pose());
		if (distance < 0.6 * goal.tolerance()) { // margin: odometry drifts a little from the true pose
			goal.succeeded(format("reached the goal by odometry (%.2f m)", distance));
			return Command.STOP;
		}
		if (distance < best - 0.05) {
			best = distance;
			bestT = tick.t();
		} else if (tick.t() - bestT > GIVE_UP_AFTER) {
			goal.aborted(format("no progress for %.0f s, %.2f m from the goal", GIVE_UP_AFTER, distance));
			return Command.STOP;
		}
		double error = odom.bearingTo(goal.pose().x(), goal.pose().y());
		double w = 2.0 * error;
		if (Math.abs(error) > 0.5) {
			goal.active(format("turning, %.1f m to go", distance));
			return new Command(0, w).clamp(robot); // turn on the spot first
		}
		Scan scan = tick.scan();
		if (scan == null) {
			return Command.STOP; // no scan yet: do not drive blind
		}
		double right = scan.minRange(-FRONT, 0);
		double left = scan.minRange(0, FRONT);
		double nearest = Math.min(left, right);
		double clearance = Math.max(0, Math.min(1, (nearest - STOP_AT) / (SLOW_FROM - STOP_AT)));
		if (clearance < 1) {
			w += AVOID_TURN * (1 - clearance) * (left < right ? -1 : 1); // away from the nearer side
			goal.active(format("obstacle %.2f m ahead, %.1f m to go", nearest, distance));
		} else {
			goal.active(format("%.1f m to go", distance));
		}
		double v = Math.min(robot.maxLinear(), 0.5 * distance) * Math.cos(error) * clearance;
		return new Command(v, w).clamp(robot);
	}

	private static String format(String pattern, Object... args) {
		return String.format(Locale.ROOT, pattern, args);
	}
}
