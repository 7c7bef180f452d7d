using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using MagnusBall;
using MagnusBall.Contact;
using MagnusBall.Flight;
using MagnusBall.Integration;
using MagnusBall.Presets;
using MagnusBall.Queries;

namespace MagnusBall.DeterminismCheck
{
    /// <summary>
    /// Flies seeded random shots (every preset, every integrator, both a z-up and a y-up frame, random launch
    /// speed, angles, spin, altitude and wind) to their landing; every 16th shot also bounces on (FlightStepper with a
    /// GroundContact and the preset's bounce law) and every 200th is aimed (AimSolver.ElevationToReach). Writes one line
    /// of hex bits per shot to the dump and keeps a hash of everything; tools/determinism-check.sh compares the dumps
    /// of CoreCLR, Mono and Mono without intrinsics, and the playground's self-test page (samples/Playground,
    /// <c>?selftest=N</c>) flies the first N shots in the browser. The random numbers come from SplitMix64, not
    /// System.Random, so that the inputs do not depend on the runtime either. One instance flies one run: make a
    /// new one to start again from the first shot.
    /// </summary>
    public sealed class DeterminismShots
    {
        private ulong _seed = 0x15A15A15A15AUL;
        private ulong _hash = 14695981039346656037UL;

        /// <summary>The hash of every bit of every shot flown so far (FNV-1a over the dumped values).</summary>
        public ulong Hash => _hash;

        /// <summary>The hash as DeterminismCheck prints it: 0x and 16 upper-case hex digits.</summary>
        public string HashText => "0x" + _hash.ToString("X16", CultureInfo.InvariantCulture);

        /// <summary>
        /// Flies the first <paramref name="shots"/> shots, writes each shot's line to <paramref name="dump"/>, and returns
        /// the summary line DeterminismCheck prints (its counts and <see cref="HashText"/>).
        /// </summary>
        public string Run(int shots, TextWriter dump)
        {
            if (shots < 0)
            {
                throw new ArgumentOutOfRangeException(nameof(shots), shots, "shots must be 0 or more.");
            }

            IReadOnlyList<SportPreset> presets = SportPresets.All;
            IIntegrator[] integrators = Array.ConvertAll(Integrators.Names, Integrators.FromName);
            var models = new Dictionary<(int, int, int), FlightModel>();
            Span<Vector3d> noSamples = Span<Vector3d>.Empty;
            int landed = 0, diverged = 0, bounced = 0, aimed = 0, solved = 0;
            var line = new System.Text.StringBuilder();

            for (int i = 0; i < shots; i++)
            {
                // Every preset, and the thesis's model (constant coefficients), which Mono steps through RK4's straight-line
                // form and CoreCLR through the general one (FlightKernel.PreferStraightLine): the same bits either way.
                int p = i % (presets.Count + 1);
                int n = (i / (presets.Count + 1)) % integrators.Length;
                bool thesis = p == presets.Count;
                SportPreset preset = presets[thesis ? 0 : p];
                IIntegrator integrator = integrators[n];
                bool yUp = Next() < 0.5;
                Vector3d up = yUp ? Vector3d.UnitY : Vector3d.UnitZ;
                Vector3d forward = Vector3d.UnitX;
                int altitude = (int)(Next() * 4); // 0, 800, 1600, 2400 m: the standard atmosphere's Pow and Exp
                if (!models.TryGetValue((p, yUp ? 1 : 0, altitude), out FlightModel? model))
                {
                    double h = 800.0 * altitude;
                    double density = Air.AtAltitude(h, null, 0.5).Density; // the standard atmosphere at h, 50 % humidity
                    model = thesis
                        ? FlightModel.Thesis(Ball.Tennis, new Air(density), Gravity.Along(up))
                        : preset.CreateModel(new Air(density), Gravity.Along(up));
                    models.Add((p, yUp ? 1 : 0, altitude), model);
                }

                // A launch a game could make: 5-70 m/s, -10..60 degrees up, +-30 degrees across, spin +-400 rad/s.
                var frame = new LaunchFrame(up, forward);
                double speed = 5 + 65 * Next();
                double elevation = (-10 + 70 * Next()) * (Math.PI / 180);
                double azimuth = (-30 + 60 * Next()) * (Math.PI / 180);
                var spin = new LaunchSpin(-400 + 800 * Next(), -200 + 400 * Next(), -50 + 100 * Next());
                Vector3d direction = frame.Direction(elevation, azimuth);
                Vector3d position = up * (0.3 + 2.5 * Next());
                var start = new FlightState(position, direction * speed, spin.AngularVelocity(direction, frame));
                double step = n < 3 ? 1.0 / 240 : 1.0 / 60;

                var predictor = new TrajectoryPredictor(model, integrator, step, FlightEventSet.ForModel(model));
                Prediction prediction = predictor.Predict(start, 12, noSamples);
                line.Clear();
                line.Append(i.ToString(CultureInfo.InvariantCulture));
                Add(line, prediction.EndState);
                Add(line, prediction.StopEvent.State);
                Add(line, prediction.Steps);
                landed += prediction.Stopped ? 1 : 0;
                diverged += prediction.Diverged ? 1 : 0;

                if (i % 16 == 0 && !prediction.Diverged)
                {
                    var flight = new FlightStepper(model, integrator, null, new GroundContact(preset.Bounce ?? CrossBounce.Hard, Plane.Ground(model)));
                    flight.Reset(start);
                    for (int k = 0; k < 480 && !flight.IsStopped; k++)
                    {
                        if (flight.TryStep(1.0 / 120) == StepOutcome.Diverged)
                        {
                            break;
                        }
                    }

                    Add(line, flight.State);
                    Add(line, flight.BounceCount);
                    bounced += flight.BounceCount > 0 ? 1 : 0;
                }

                if (i % 200 == 0)
                {
                    var solver = new AimSolver(model, integrator, 1.0 / 120, Plane.Ground(model));
                    double range = 3 + 40 * Next();
                    Vector3d target = forward * range + frame.Side * (-2 + 4 * Next());
                    AimSolution aim = solver.ElevationToReach(position, speed, spin, target);
                    Add(line, (long)aim.Status);
                    Add(line, aim.Velocity);
                    Add(line, aim.Miss);
                    aimed++;
                    solved += aim.IsSolved ? 1 : 0;
                }

                dump.WriteLine(line.ToString());
            }

            return
                $"determinism: {shots} shots ({presets.Count} presets and the thesis model x {integrators.Length} integrators), {landed} landed, {diverged} diverged, " +
                $"{bounced} bounced, {aimed} aimed ({solved} solved); hash {HashText}";
        }

        /// <summary>SplitMix64, as a double in [0, 1) with 53 random bits (exact).</summary>
        private double Next()
        {
            ulong z = _seed += 0x9E3779B97F4A7C15UL;
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
            z ^= z >> 31;
            return (z >> 11) * (1.0 / 9007199254740992.0);
        }

        private void Add(System.Text.StringBuilder line, in FlightState state)
        {
            Add(line, state.Position);
            Add(line, state.Velocity);
            Add(line, state.AngularVelocity);
            Add(line, state.Time);
        }

        private void Add(System.Text.StringBuilder line, in Vector3d v)
        {
            Add(line, v.X);
            Add(line, v.Y);
            Add(line, v.Z);
        }

        private void Add(System.Text.StringBuilder line, double value) => Add(line, BitConverter.DoubleToInt64Bits(value));

        private void Add(System.Text.StringBuilder line, long bits)
        {
            line.Append(' ').Append(bits.ToString("X", CultureInfo.InvariantCulture));
            for (int b = 0; b < 64; b += 8)
            {
                _hash = (_hash ^ (((ulong)bits >> b) & 0xFF)) * 1099511628211UL;
            }
        }
    }
}
