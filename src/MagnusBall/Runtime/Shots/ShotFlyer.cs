using System;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Queries;

namespace MagnusBall.Shots
{
    /// <summary>
    /// Flies shots given in game terms (<see cref="ShotLaunch"/>) in a <see cref="ShotFrame"/> and reports them in game terms:
    /// a <see cref="FlightSummary"/> for any sport, a <see cref="PitchResult"/> (plate crossing and Statcast's break) for a
    /// baseball pitch. Each call allocates its result (the summary keeps the flight's samples for
    /// <see cref="FlightSummary.TryCross"/>); for per-frame work use <see cref="TrajectoryPredictor"/> with
    /// <see cref="LaunchState"/>. A flyer reuses one sample buffer between calls, so it is not thread-safe: create one per thread.
    /// </summary>
    /// <remarks>
    /// The flight is stepped with RK4 at 1/240 s (substepped where a light, fast ball would need it), which puts a landing
    /// within a millimetre of a converged one for every preset's shots; events (landing, apex, plate) are located on each
    /// step's dense output.
    /// </remarks>
    public sealed class ShotFlyer
    {
        private const double Step = 1.0 / 240, MaxDurationSeconds = 20;
        private readonly FlightModel _model;
        private readonly ShotFrame _frame;
        private FlightState[]? _samples; // reused between calls: 20 s at 1/240 s, 0.4 MB

        /// <summary>Creates a flyer for <paramref name="model"/> (for example <c>SportPresets.Golf.CreateModel(air, gravity)</c>) in <paramref name="frame"/>.</summary>
        /// <param name="model">The flight model.</param>
        /// <param name="frame">The frame; its up must be the model's up (-gravity) when gravity is not zero.</param>
        /// <exception cref="ArgumentException">model is null, frame is the default frame, or its up is not the model's up.</exception>
        public ShotFlyer(FlightModel model, ShotFrame frame)
        {
            _model = Require.NotNull(model, nameof(model));
            if (frame.IsDefault)
            {
                throw new ArgumentException("frame must be built from up, forward and right (or ShotFrame.ZUp, ShotFrame.YUp); got the default frame.", nameof(frame));
            }

            if (model.Up.LengthSquared > 0 && !(Vector3d.Dot(model.Up, frame.Up) > 1 - 1e-9))
            {
                throw new ArgumentException(
                    $"frame's up must be the model's up (-gravity normalised), {model.Up}; got {frame.Up} (a y-up frame with z-up gravity?).", nameof(frame));
            }

            _frame = frame;
        }

        /// <summary>The launch state of <paramref name="launch"/> from the given point of the frame, for a <see cref="TrajectoryPredictor"/>.</summary>
        /// <param name="launch">The launch.</param>
        /// <param name="forwardMetres">Launch point along forward from the frame's origin, m; finite.</param>
        /// <param name="rightMetres">Launch point to the right, m; finite.</param>
        /// <param name="upMetres">Height of the ball's centre above the ground, m; finite.</param>
        /// <exception cref="ArgumentOutOfRangeException">A coordinate is not finite.</exception>
        public FlightState LaunchState(ShotLaunch launch, double forwardMetres, double rightMetres, double upMetres) =>
            launch.ToState(_frame, _frame.At(forwardMetres, rightMetres, upMetres), 0);

        /// <summary>Flies <paramref name="launch"/> from the given point until it lands (or 20 s pass) and summarises the flight.</summary>
        /// <param name="launch">The launch.</param>
        /// <param name="forwardMetres">Launch point along forward from the frame's origin, m; finite.</param>
        /// <param name="rightMetres">Launch point to the right, m; finite.</param>
        /// <param name="upMetres">Height of the ball's centre above the ground, m; finite. Null (the default): the ball's radius, a ball
        /// resting on the ground (a kick, a tee shot's ball on the turf).</param>
        /// <returns>Carry, apex, flight time, landing angle and speed, side and curve.</returns>
        /// <exception cref="ArgumentOutOfRangeException">A coordinate is not finite.</exception>
        /// <exception cref="ArgumentException">The flight diverged (a speed far beyond any ball's, near the speed of light); the message names launch.</exception>
        public FlightSummary Fly(ShotLaunch launch, double forwardMetres = 0, double rightMetres = 0, double? upMetres = null)
        {
            FlightState start = LaunchState(launch, forwardMetres, rightMetres, upMetres ?? _model.Ball.Radius);
            return Summarise(_model, start, Array.Empty<Plane>(), out _);
        }

        /// <summary>
        /// Flies a baseball pitch from its release point (the frame's origin at the front of the pitcher's rubber on the field,
        /// forward toward home plate: <see cref="BaseballField"/>) and reports where it crosses the front of home plate and its
        /// break as Statcast publishes it: the induced movement, against the same pitch flown without the Magnus force, from
        /// the release to the front of the plate (Baseball Savant's "induced vertical break" and "horizontal break", which
        /// remove gravity; PITCHf/x measured the same movement from 40 ft only, about 1.8 times smaller).
        /// </summary>
        /// <param name="launch">The pitch (see <see cref="ShotLaunch.Statcast(Speed, double, double, double, string, double)"/>).</param>
        /// <param name="releaseForwardMetres">Release point in front of the rubber (Statcast's extension), m; finite.</param>
        /// <param name="releaseRightMetres">Release point to the pitcher's right, m; finite.</param>
        /// <param name="releaseUpMetres">Release height above the field, m; finite.</param>
        /// <returns>The plate crossing and the break; <see cref="PitchResult.CrossesPlate"/> false when it lands first.</returns>
        /// <exception cref="ArgumentOutOfRangeException">A coordinate is not finite.</exception>
        /// <exception cref="ArgumentException">The flight diverged; the message names launch.</exception>
        public PitchResult Pitch(ShotLaunch launch, double releaseForwardMetres, double releaseRightMetres, double releaseUpMetres)
        {
            FlightState release = LaunchState(launch, releaseForwardMetres, releaseRightMetres, releaseUpMetres);
            var plate = new[] { new Plane(_frame.At(BaseballField.RubberToPlateMetres - BaseballField.PlateDepthMetres, 0, 0), _frame.Forward) };
            Summarise(_model, release, plate, out FlightEvent? atPlate);
            if (atPlate == null)
            {
                return default;
            }

            Summarise(_model.WithLift(null), release, plate, out FlightEvent? spinless);
            Vector3d p = _frame.ToFrame(atPlate.Value.Position);
            Vector3d q = spinless == null ? p : _frame.ToFrame(spinless.Value.Position);
            return new PitchResult(
                atPlate.Value.Time - release.Time, atPlate.Value.Velocity.Length, p.Z, -p.Y, p.Z - q.Z, -(p.Y - q.Y));
        }

        // Flies start with model until it lands; returns the summary and the first crossing of planes[0], if any.
        private FlightSummary Summarise(FlightModel model, in FlightState start, Plane[] planes, out FlightEvent? crossing)
        {
            var ground = new Plane(_frame.At(0, 0, model.Ball.Radius), _frame.Up);
            var predictor = new TrajectoryPredictor(model, StableIntegrator.RungeKutta4, Step, new FlightEventSet(model.Up, ground, planes));
            FlightState[] samples = _samples ??= new FlightState[(int)(MaxDurationSeconds / Step) + 2];
            var events = new FlightEvent[16];
            Prediction p = predictor.Predict(start, MaxDurationSeconds, samples, events);
            if (p.Diverged || p.TimeCannotAdvance)
            {
                throw new ArgumentException(
                    $"launch must be a flight that can be flown: from {start} it {(p.Diverged ? "diverged" : "could not advance its time")}, " +
                    $"a speed of {start.Velocity.Length:R} m/s is far beyond any ball's (see SportLimits).", "launch");
            }

            crossing = null;
            double apexUp = double.NegativeInfinity;
            for (int i = 0; i < p.EventCount; i++)
            {
                FlightEvent e = events[i];
                if (e.Kind == FlightEventKinds.Apex && apexUp == double.NegativeInfinity)
                {
                    apexUp = _frame.ToFrame(e.Position).Z;
                }
                else if (e.Kind == FlightEventKinds.PlaneCrossing && crossing == null)
                {
                    crossing = e;
                }
            }

            int n = p.SampleCount;
            var times = new double[n];
            var positions = new Vector3d[n];
            var velocities = new Vector3d[n];
            for (int i = 0; i < n; i++)
            {
                times[i] = samples[i].Time;
                positions[i] = _frame.ToFrame(samples[i].Position);
                velocities[i] = _frame.VectorToFrame(samples[i].Velocity);
            }

            return new FlightSummary(times, positions, velocities, p.Stopped, apexUp, model.Ball.Radius);
        }
    }
}
