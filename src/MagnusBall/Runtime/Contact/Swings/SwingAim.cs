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

        /// <summary>The launch the swing gives, with its angles measured in the aim solver's frame (up, forward toward the target).</summary>
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
    /// elevation) and the swing's azimuth (which sets the direction) are solved. The residual is the difference between
    /// the direction the aim solver finds for the launch's speed and spin (by effect) and the direction the swing
    /// launches in. It is driven to zero by Broyden's method, started from the 2 x 2 Jacobian of the launch angles by
    /// central differences of the swing alone (four impacts, no flights); the updates learn how the aim solver's answer
    /// moves with the launch speed and spin, and a step that makes the residual worse or the target unreachable is
    /// halved (up to 12 times). Each residual costs one aim solve; it stops when the directions agree to
    /// <see cref="AngleTolerance"/>, after at most <see cref="MaximumIterations"/> steps.</para>
    /// <para>Holds its <see cref="AimSolver"/>, which is not thread-safe: one <see cref="SwingAim"/> per thread.</para>
    /// </remarks>
    public sealed class SwingAim
    {
        /// <summary>The launch direction agrees with the aim solver's to this, rad.</summary>
        public const double AngleTolerance = 1e-9;

        /// <summary>The most outer iterations (aim solves) of one solve.</summary>
        public const int MaximumIterations = 40;

        /// <summary>
        /// The aim solver's solution counts only when it passes this close to the target, m (its angle tolerance gives
        /// about 1e-7 m at tennis distances; a solver that returns its lower elevation limit can be farther).
        /// </summary>
        public const double MissTolerance = 1e-4;

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
        /// ground: lands there). The swing is oriented in <paramref name="frame"/>; the launch is compared with the aim
        /// solver's in the solver's frame (its up, forward toward the target).
        /// </summary>
        /// <param name="swing">The swing; its face tilt and azimuth are the starting guess.</param>
        /// <param name="frame">The frame the swing's angles are given in (its azimuth is from this frame's forward); not the default frame.</param>
        /// <param name="position">The ball's centre at impact, m; finite.</param>
        /// <param name="incomingVelocity">The ball's velocity before the impact, m/s; finite.</param>
        /// <param name="incomingSpin">The ball's angular velocity before the impact, rad/s; finite.</param>
        /// <param name="target">The target point, m; finite, not straight above or below the position.</param>
        /// <param name="maximumAzimuthDegrees">The largest launch azimuth from the target direction the aim solver tries, degrees; in (0, 89].</param>
        /// <returns>The solved swing, or <see cref="AimStatus.Unreachable"/> when the swing cannot reach the target (never an exception for finite input).</returns>
        /// <exception cref="ArgumentException">An argument is not finite, or the target is straight above or below the position; the message names it.</exception>
        public RacketAim RacketFaceToReach(
            in RacketSwing swing, in LaunchFrame frame, in Vector3d position, in Vector3d incomingVelocity, in Vector3d incomingSpin, in Vector3d target,
            double maximumAzimuthDegrees = 45)
        {
            SwingGeometry.RequireFrame(frame, nameof(frame));
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

            var aimFrame = new LaunchFrame(up, horizontal);
            RacketSwing current = swing;
            if (!Residual(current, frame, aimFrame, position, incomingVelocity, incomingSpin, target, maximumAzimuthDegrees,
                    out SwingLaunch launch, out AimSolution aim, out double r1, out double r2))
            {
                return new RacketAim(AimStatus.Unreachable, current, launch, aim, 1);
            }

            // Broyden's method on r(x) = aim angles - launch angles, x = (face tilt, azimuth) in degrees, started from
            // the Jacobian of -launch angles (central differences of the swing alone: the aim's own response to speed
            // and spin is learnt by the updates), with backtracking when a step makes the residual worse or unreachable.
            if (!LaunchJacobian(current, frame, aimFrame, position, incomingVelocity, incomingSpin, out double j11, out double j12, out double j21, out double j22))
            {
                return new RacketAim(AimStatus.Unreachable, current, launch, aim, 1);
            }

            j11 = -j11; j12 = -j12; j21 = -j21; j22 = -j22;
            for (int iteration = 1; iteration <= MaximumIterations; iteration++)
            {
                if (Math.Abs(r1) <= AngleTolerance && Math.Abs(r2) <= AngleTolerance)
                {
                    return new RacketAim(AimStatus.Solved, current, launch, aim, iteration);
                }

                double determinant = j11 * j22 - j12 * j21;
                if (!(Math.Abs(determinant) > 1e-300) || !double.IsFinite(determinant))
                {
                    break;
                }

                // Newton step: J dx = -r.
                double dx1 = -(r1 * j22 - r2 * j12) / determinant;
                double dx2 = -(j11 * r2 - j21 * r1) / determinant;
                double norm = Math.Sqrt(r1 * r1 + r2 * r2);
                bool accepted = false;
                double scale = 1;
                for (int halving = 0; halving < 12 && !accepted; halving++, scale *= 0.5)
                {
                    double tilt = current.FaceTiltDegrees + scale * dx1, azimuth = current.AzimuthDegrees + scale * dx2;
                    if (!(tilt >= -80 && tilt <= 80 && azimuth >= -90 && azimuth <= 90))
                    {
                        continue;
                    }

                    RacketSwing trial = current.WithFace(tilt, azimuth);
                    if (!Residual(trial, frame, aimFrame, position, incomingVelocity, incomingSpin, target, maximumAzimuthDegrees,
                            out SwingLaunch trialLaunch, out AimSolution trialAim, out double s1, out double s2))
                    {
                        continue;
                    }

                    if (Math.Sqrt(s1 * s1 + s2 * s2) >= norm && halving < 11)
                    {
                        continue;
                    }

                    // Broyden update with the step taken (degrees) and the change of the residual (rad).
                    double h1 = scale * dx1, h2 = scale * dx2, hh = h1 * h1 + h2 * h2;
                    double y1 = s1 - r1 - (j11 * h1 + j12 * h2), y2 = s2 - r2 - (j21 * h1 + j22 * h2);
                    if (hh > 0)
                    {
                        j11 += y1 * h1 / hh; j12 += y1 * h2 / hh; j21 += y2 * h1 / hh; j22 += y2 * h2 / hh;
                    }

                    current = trial;
                    launch = trialLaunch;
                    aim = trialAim;
                    r1 = s1;
                    r2 = s2;
                    accepted = true;
                }

                if (!accepted)
                {
                    break;
                }
            }

            return new RacketAim(AimStatus.Unreachable, current, launch, aim, MaximumIterations);
        }

        private bool Residual(
            in RacketSwing swing, in LaunchFrame frame, in LaunchFrame aimFrame, in Vector3d position, in Vector3d velocity, in Vector3d spin,
            in Vector3d target, double maximumAzimuthDegrees, out SwingLaunch launch, out AimSolution aim, out double elevationError, out double azimuthError)
        {
            elevationError = azimuthError = double.NaN;
            aim = default;
            launch = new SwingLaunch(swing.Hit(Ball, frame, position, velocity, spin).Impact, aimFrame);
            if (!launch.IsHit || !(launch.Speed > 0))
            {
                return false;
            }

            aim = Solver.AnglesToReach(position, launch.Speed, launch.LaunchSpin, target, maximumAzimuthDegrees);
            if (!aim.IsSolved || !(aim.Miss <= MissTolerance))
            {
                return false;
            }

            elevationError = Wrap(aim.ElevationRadians - launch.ElevationRadians);
            azimuthError = Wrap(aim.AzimuthRadians - launch.AzimuthRadians);
            return true;
        }

        private bool LaunchJacobian(
            in RacketSwing current, in LaunchFrame frame, in LaunchFrame aimFrame, in Vector3d position, in Vector3d velocity, in Vector3d spin,
            out double j11, out double j12, out double j21, out double j22)
        {
            j11 = j12 = j21 = j22 = 0;
            double tilt = current.FaceTiltDegrees, azimuth = current.AzimuthDegrees;
            if (!TryAngles(current, tilt + DifferenceDegrees, azimuth, frame, position, velocity, spin, out double e1, out double a1, aimFrame) ||
                !TryAngles(current, tilt - DifferenceDegrees, azimuth, frame, position, velocity, spin, out double e2, out double a2, aimFrame) ||
                !TryAngles(current, tilt, azimuth + DifferenceDegrees, frame, position, velocity, spin, out double e3, out double a3, aimFrame) ||
                !TryAngles(current, tilt, azimuth - DifferenceDegrees, frame, position, velocity, spin, out double e4, out double a4, aimFrame))
            {
                return false;
            }

            double h = 2 * DifferenceDegrees;
            j11 = (e1 - e2) / h;
            j21 = Wrap(a1 - a2) / h;
            j12 = (e3 - e4) / h;
            j22 = Wrap(a3 - a4) / h;
            return true;
        }

        private bool TryAngles(
            in RacketSwing swing, double tilt, double azimuth, in LaunchFrame frame, in Vector3d position, in Vector3d velocity, in Vector3d spin,
            out double elevation, out double launchAzimuth, in LaunchFrame aimFrame)
        {
            elevation = launchAzimuth = 0;
            if (!(tilt >= -80 && tilt <= 80 && azimuth >= -90 && azimuth <= 90))
            {
                return false;
            }

            var launch = new SwingLaunch(swing.WithFace(tilt, azimuth).Hit(Ball, frame, position, velocity, spin).Impact, aimFrame);
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
