// AimSolver, part: what every solve shares around its core: the target's frame and goal, an obstacle's and a via shape's
// goals and the checks of an answer against them, and the ends of a solve (Finish, Unreachable). The public solves are in
// AimSolver.cs.
using System;

namespace MagnusBall.Queries
{
    public sealed partial class AimSolver
    {
        private AimSolution Unreachable(double speed, double azimuth) =>
            new AimSolution(AimStatus.Unreachable, speed, 0, azimuth, default, default, default, double.PositiveInfinity, _trials.Flights);

        // A solution with the solve's flights so far (a solution kept from an earlier trial counts only the flights until then).
        // A solve that reached its work cap says so, whatever its search ended on.
        private AimSolution Finish(in AimSolution s) =>
            _trials.WorkLimitReached
                ? new AimSolution(AimStatus.WorkLimitReached, s.Speed, s.ElevationRadians, s.AzimuthFromTargetRadians, s.Velocity, s.AngularVelocity, s.Arrival, s.Miss, s.Simulations)
                : s;

        private AimSolution WithFlights(in AimSolution s, AimStatus? status = null) =>
            new AimSolution(status ?? s.Status, s.Speed, s.ElevationRadians, s.AzimuthFromTargetRadians, s.Velocity, s.AngularVelocity, s.Arrival, s.Miss, _trials.Flights);

        /// <summary>
        /// The goal of clearing <paramref name="obstacle"/> on the way to <paramref name="goal"/>'s target: its plane across the
        /// target frame's forward at its distance, the ball's centre at least a radius above its top. Checks the obstacle
        /// against the target: it must stand short of it.
        /// </summary>
        private AimGoal ObstacleGoal(in AimGoal goal, in AimObstacle obstacle)
        {
            double toTarget = Vector3d.DotOfDifference(goal.Target, goal.Position, goal.Frame.Forward);
            if (!(obstacle.DistanceMeters < toTarget))
            {
                throw new ArgumentException(
                    $"obstacle must stand short of the target: its distance must be in (0, {Require.Format(toTarget)}) m (the target's horizontal distance); got {Require.Format(obstacle.DistanceMeters)} m.",
                    nameof(obstacle));
            }

            Vector3d required = Ground.Point + Ground.Normal * (obstacle.TopHeightMeters + Model.Ball.Radius);
            if (!required.IsFinite)
            {
                throw new ArgumentException(
                    $"obstacle's top must keep the required point (the ground's point plus its normal times the top height and the ball's radius) within the range of a double; got {Require.Format(obstacle.TopHeightMeters)} m.",
                    nameof(obstacle));
            }

            var plane = new Plane(goal.Position + goal.Frame.Forward * obstacle.DistanceMeters, goal.Frame.Forward);
            return new AimGoal(goal.Position, goal.Frame, goal.Spin, plane, required, missToTarget: false);
        }

        /// <summary>
        /// A solved target launch checked against the obstacle by one trial to its plane: itself when the ball's bottom passes
        /// above the top; else Blocked, with the clearance (negative) as the miss. Unsolved results pass through.
        /// </summary>
        private AimSolution CheckClears(in AimSolution s, in AimGoal obstacleGoal)
        {
            if (!s.IsSolved)
            {
                return s;
            }

            double clearance = _trials.Margin(obstacleGoal, s.Speed, s.ElevationRadians, s.AzimuthFromTargetRadians, out _);
            return clearance >= 0
                ? WithFlights(s)
                : new AimSolution(AimStatus.Blocked, s.Speed, s.ElevationRadians, s.AzimuthFromTargetRadians, s.Velocity, s.AngularVelocity, s.Arrival,
                    double.IsNaN(clearance) ? double.NegativeInfinity : clearance, _trials.Flights);
        }

        /// <summary>Whether a solve's answer is checked after its search: against an obstacle, or among the solver's shapes.</summary>
        private bool Checks(in AimObstacle obstacle) => !obstacle.IsNone || _trials.HasShapes;

        /// <summary>
        /// A solved target launch checked against the obstacle (<see cref="CheckClears"/>, where there is one) and then among the
        /// solver's shapes by one flight to its plane: Blocked, with the solved trial's miss, where it touches a shape before it
        /// arrives (other than a bank shot's via shape, first). Unsolved results pass through.
        /// </summary>
        private AimSolution CheckAll(in AimSolution s, in AimGoal goal, in AimObstacle obstacle, in AimGoal wall)
        {
            AimSolution c = obstacle.IsNone ? s : CheckClears(s, wall);
            if (!c.IsSolved || !_trials.HasShapes)
            {
                return c;
            }

            return _trials.ClearsShapes(goal, c, out _)
                ? WithFlights(c)
                : new AimSolution(AimStatus.Blocked, c.Speed, c.ElevationRadians, c.AzimuthFromTargetRadians, c.Velocity, c.AngularVelocity, c.Arrival, c.Miss, _trials.Flights);
        }

        /// <summary>
        /// A bank shot's goal: <paramref name="goal"/> with its plane through the target facing the horizontal direction from
        /// the middle of the via shapes' bounds to the target (where that is vertical, back along the frame's forward).
        /// </summary>
        /// <exception cref="ArgumentException">No shape of the solver has id <paramref name="viaShapeId"/>.</exception>
        private AimGoal ViaGoal(in AimGoal goal, int? viaShapeId)
        {
            if (viaShapeId == null)
            {
                return goal;
            }

            int id = viaShapeId.Value;
            if (!_trials.HasShape(id))
            {
                throw new ArgumentException(
                    $"viaShapeId must be the id of one of the solver's shapes ({(_trials.HasShapes ? "it has none of id " + id : "it has no shapes: give them to the constructor")}); got {id}.",
                    nameof(viaShapeId));
            }

            Vector3d up = Model.Up;
            Vector3d back = goal.Target - _trials.ShapeCentre(id);
            back -= up * Vector3d.Dot(back, up);
            Vector3d normal = back.Length > 1e-9 ? back.NormalizedOrZero() : -goal.Frame.Forward;
            return new AimGoal(goal.Position, goal.Frame, goal.Spin, new Plane(goal.Target, normal), goal.Target, missToTarget: true, hasVia: true, viaId: id);
        }

        private static void CheckTarget(in Vector3d position, in Vector3d target)
        {
            Require.Finite(position, nameof(position));
            Require.Finite(target, nameof(target));
        }

        private AimGoal TargetGoal(in Vector3d position, in Vector3d target, in LaunchSpin spin)
        {
            LaunchFrame frame = TargetFrame(Model.Up, position, target);
            return new AimGoal(position, frame, spin, new Plane(target, frame.Forward), target, missToTarget: true);
        }

        /// <summary>
        /// The frame of a target solve: <paramref name="up"/>, forward the horizontal direction from
        /// <paramref name="position"/> to <paramref name="target"/> (formed from quarters where the difference overflows).
        /// </summary>
        /// <exception cref="ArgumentException">The target is within 1e-6 m of straight above or below the position (names target).</exception>
        internal static LaunchFrame TargetFrame(in Vector3d up, in Vector3d position, in Vector3d target)
        {
            Vector3d toTarget = target - position;
            Vector3d horizontal = toTarget - up * Vector3d.Dot(toTarget, up);
            double length = horizontal.Length;
            if (!double.IsFinite(length))
            {
                // The target near 1e308 away: the difference (or its part along up) overflowed. Its quarter does not
                // (quartering is exact but for subnormals), and the frame needs only the direction.
                Vector3d quarter = 0.25 * target - 0.25 * position;
                horizontal = quarter - up * Vector3d.Dot(quarter, up);
                length = 4 * horizontal.Length;
            }

            if (!(length > 1e-6))
            {
                throw new ArgumentException(
                    $"target must not be straight above or below the launch point (horizontal distance {Require.Format(length)} m).",
                    nameof(target));
            }

            try
            {
                return new LaunchFrame(up, horizontal);
            }
            catch (ArgumentException)
            {
                // The horizontal part is over 1e-6 m but within LaunchFrame's 1e-9 of its own length of up: rounding left
                // over from a target far along up (a horizontal of 4e292 m beside 1.8e308 m along a tilted up). The caller
                // gave a target, not a forward: name it.
                throw new ArgumentException(
                    $"target must not be straight above or below the launch point (horizontal distance {Require.Format(length)} m is rounding beside its distance along up).",
                    nameof(target));
            }
        }

        // The horizontal path from the launch point to the target plane along the azimuth (NaN when it never gets there).
        private static double PathToTarget(in AimGoal goal, double azimuth)
        {
            double along = Vector3d.Dot(goal.Frame.Forward, goal.Frame.Direction(0, azimuth));
            return along > 0 ? Vector3d.DotOfDifference(goal.Target, goal.Position, goal.Frame.Forward) / along : double.NaN;
        }
    }
}
