using System;
using MagnusBall.Queries;

namespace MagnusBall.Contact.Swings
{
    /// <summary>The result of <see cref="SwingAim.RacketFaceToReach"/>: the swing found and the launch it gives.</summary>
    public readonly struct RacketAim
    {
        /// <summary>Creates a result.</summary>
        /// <param name="status">Solved or unreachable.</param>
        /// <param name="swing">The swing (the last one tried when unreachable).</param>
        /// <param name="launch">Its launch.</param>
        /// <param name="aim">The aim solver's launch for that swing's speed and spin.</param>
        /// <param name="iterations">Outer iterations used.</param>
        public RacketAim(AimStatus status, in RacketSwing swing, in SwingLaunch launch, in AimSolution aim, int iterations)
        {
            Status = status;
            Swing = swing;
            Launch = launch;
            Aim = aim;
            Iterations = iterations;
        }

        /// <summary>Solved or unreachable.</summary>
        public AimStatus Status { get; }

        /// <summary>True when solved.</summary>
        public bool IsSolved => Status == AimStatus.Solved;

        /// <summary>The swing: the input's speed, path, impact point and face turn, with the face tilt and azimuth solved.</summary>
        public RacketSwing Swing { get; }

        /// <summary>The launch the swing gives.</summary>
        public SwingLaunch Launch { get; }

        /// <summary>The aim solver's solution for the launch's speed and spin (its direction is the launch's to <see cref="SwingAim.AngleTolerance"/>).</summary>
        public AimSolution Aim { get; }

        /// <summary>Outer iterations (each one aim solve).</summary>
        public int Iterations { get; }

        /// <inheritdoc />
        public override string ToString() => $"RacketAim({Status}, {Swing}, {Launch}, {Iterations} iterations)";
    }

    /// <summary>
    /// The inverse of the swing helpers, for AI players: the swing that sends the ball to a target. Built on
    /// <see cref="AimSolver"/>: the aim solver finds the launch direction that reaches the target for the launch's speed
    /// and spin, and the swing's face is turned until the swing launches the ball in that direction.
    /// </summary>
    /// <remarks>
    /// <para>A racket swing's speed, path and impact point are the player's; the face tilt (which sets the launch
    /// elevation) and the swing's azimuth (which sets the direction) are solved. Each outer iteration asks the aim
    /// solver for the direction that reaches the target with the current launch's speed and spin (by effect), then takes
    /// one Newton step of the face tilt and azimuth toward that direction, with the 2 x 2 Jacobian of the launch angles by
    /// central differences of the swing (cheap: four impacts, no flights). Changing the face changes the launch speed and
    /// spin a little, so the aim solve is repeated until the launch direction agrees with the aim solver's to
    /// <see cref="AngleTolerance"/>; at most <see cref="MaximumIterations"/> iterations.</para>
    /// <para>Holds its <see cref="AimSolver"/>, which is not thread-safe: one <see cref="SwingAim"/> per thread.</para>
    /// </remarks>
    public sealed class SwingAim
    {
        /// <summary>The launch direction agrees with the aim solver's to this, rad.</summary>
        public const double AngleTolerance = 1e-9;

        /// <summary>The most outer iterations (aim solves) of one solve.</summary>
        public const int MaximumIterations = 40;

        private const double DifferenceDegrees = 1e-4;

        /// <summary>Creates the inverse on an aim solver.</summary>
        /// <param name="solver">The aim solver (model, integrator, step, ground); not null.</param>
        /// <param name="ball">The ball the swings hit; not null (its mass and radius enter the impact).</param>
        /// <exception cref="ArgumentNullException">An argument is null.</exception>
        public SwingAim(AimSolver solver, Ball ball)
        {
            Solver = Require.NotNull(solver, nameof(solver));
            Ball = Require.NotNull(ball, nameof(ball));
        }

        /// <summary>The aim solver.</summary>
        public AimSolver Solver { get; }

        /// <summary>The ball.</summary>
        public Ball Ball { get; }

        /// <summary>
        /// The face tilt and azimuth with which <paramref name="swing"/> (its speed, path, impact point and face turn kept)
        /// sends a ball arriving at <paramref name="position"/> through <paramref name="target"/> (for a target on the
        /// ground: lands there). The frame is the solver's up with forward toward the target.
        /// </summary>
        /// <param name="swing">The swing; its face tilt and azimuth are the starting guess.</param>
        /// <param name="position">The ball's centre at impact, m; finite.</param>
        /// <param name="incomingVelocity">The ball's velocity before the impact, m/s; finite.</param>
        /// <param name="incomingSpin">The ball's angular velocity before the impact, rad/s; finite.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the position.</param>
        /// <param name="maximumAzimuthDegrees">The largest launch azimuth from the target direction the aim solver tries, degrees; in (0, 89].</param>
        /// <returns>The solved swing, or <see cref="AimStatus.Unreachable"/> when the swing cannot reach the target (never an exception for finite input).</returns>
        /// <exception cref="ArgumentException">An argument is not finite, or the target is straight above or below the position; the message names it.</exception>
        public RacketAim RacketFaceToReach(
            in RacketSwing swing, in Vector3d position, in Vector3d incomingVelocity, in Vector3d incomingSpin, in Vector3d target,
            double maximumAzimuthDegrees = 45)
        {
            Require.Finite(position, nameof(position));
            Require.Finite(incomingVelocity, nameof(incomingVelocity));
            Require.Finite(incomingSpin, nameof(incomingSpin));
            Require.Finite(target, nameof(target));
            Require.InRange(maximumAzimuthDegrees, double.Epsilon, 89, nameof(maximumAzimuthDegrees));
            if (swing.Speed == 0)
            {
                throw new ArgumentException("swing must be built by a RacketSwing constructor; got the default value.", nameof(swing));
            }

            Vector3d up = Solver.Model.Up;
            Vector3d toTarget = target - position;
            Vector3d horizontal = toTarget - up * Vector3d.Dot(toTarget, up);
            if (!(horizontal.Length > 1e-9))
            {
                throw new ArgumentException("target must not be straight above or below position.", nameof(target));
            }

            var frame = new LaunchFrame(up, horizontal);
            RacketSwing current = swing;
            SwingLaunch launch = default;
            AimSolution aim = default;
            for (int iteration = 1; iteration <= MaximumIterations; iteration++)
            {
                launch = current.Hit(Ball, frame, position, incomingVelocity, incomingSpin);
                if (!launch.IsHit || !(launch.Speed > 0))
                {
                    return new RacketAim(AimStatus.Unreachable, current, launch, aim, iteration);
                }

                aim = Solver.AnglesToReach(position, launch.Speed, launch.LaunchSpin, target, maximumAzimuthDegrees);
                if (!aim.IsSolved)
                {
                    return new RacketAim(AimStatus.Unreachable, current, launch, aim, iteration);
                }

                double elevationError = Wrap(aim.ElevationRadians - launch.ElevationRadians);
                double azimuthError = Wrap(aim.AzimuthRadians - launch.AzimuthRadians);
                if (Math.Abs(elevationError) <= AngleTolerance && Math.Abs(azimuthError) <= AngleTolerance)
                {
                    return new RacketAim(AimStatus.Solved, current, launch, aim, iteration);
                }

                // Jacobian of (elevation, azimuth) by (face tilt, azimuth), degrees to radians, central differences.
                double tilt = current.FaceTiltDegrees, azimuth = current.AzimuthDegrees;
                if (!TryAngles(current, tilt + DifferenceDegrees, azimuth, frame, position, incomingVelocity, incomingSpin, out double e1, out double a1) ||
                    !TryAngles(current, tilt - DifferenceDegrees, azimuth, frame, position, incomingVelocity, incomingSpin, out double e2, out double a2) ||
                    !TryAngles(current, tilt, azimuth + DifferenceDegrees, frame, position, incomingVelocity, incomingSpin, out double e3, out double a3) ||
                    !TryAngles(current, tilt, azimuth - DifferenceDegrees, frame, position, incomingVelocity, incomingSpin, out double e4, out double a4))
                {
                    return new RacketAim(AimStatus.Unreachable, current, launch, aim, iteration);
                }

                double h = 2 * DifferenceDegrees;
                double j11 = (e1 - e2) / h, j21 = Wrap(a1 - a2) / h, j12 = (e3 - e4) / h, j22 = Wrap(a3 - a4) / h;
                double determinant = j11 * j22 - j12 * j21;
                if (!(Math.Abs(determinant) > 1e-300) || !double.IsFinite(determinant))
                {
                    return new RacketAim(AimStatus.Unreachable, current, launch, aim, iteration);
                }

                double dTilt = (elevationError * j22 - azimuthError * j12) / determinant;
                double dAzimuth = (j11 * azimuthError - j21 * elevationError) / determinant;
                double nextTilt = tilt + dTilt, nextAzimuth = azimuth + dAzimuth;
                if (!(nextTilt >= -80 && nextTilt <= 80 && nextAzimuth >= -90 && nextAzimuth <= 90))
                {
                    return new RacketAim(AimStatus.Unreachable, current, launch, aim, iteration);
                }

                current = current.WithFace(nextTilt, nextAzimuth);
            }

            return new RacketAim(AimStatus.Unreachable, current, launch, aim, MaximumIterations);
        }

        private bool TryAngles(
            in RacketSwing swing, double tilt, double azimuth, in LaunchFrame frame, in Vector3d position, in Vector3d velocity, in Vector3d spin,
            out double elevation, out double launchAzimuth)
        {
            elevation = launchAzimuth = 0;
            if (!(tilt >= -80 && tilt <= 80 && azimuth >= -90 && azimuth <= 90))
            {
                return false;
            }

            SwingLaunch launch = swing.WithFace(tilt, azimuth).Hit(Ball, frame, position, velocity, spin);
            if (!launch.IsHit)
            {
                return false;
            }

            elevation = launch.ElevationRadians;
            launchAzimuth = launch.AzimuthRadians;
            return true;
        }

        private static double Wrap(double angle) =>
            angle > Math.PI ? angle - 2 * Math.PI : angle < -Math.PI ? angle + 2 * Math.PI : angle;
    }
}
