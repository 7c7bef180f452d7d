using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;
using MagnusBall.Queries;

namespace MagnusBall.Cli
{
    /// <summary>
    /// `magnusball aim FILE`: the library's <see cref="AimSolver"/> behind a JSON file. Each entry of "aims"
    /// has the flight fields of a scenario (ball, air, gravity, aero, spinDecay, integrator, step, maxTime,
    /// ground), a "launch" (position and spin by effect) and a "find" object naming the solve and its inputs.
    /// See docs/cli.md.
    /// </summary>
    internal static class AimCommand
    {
        /// <summary>The solves "find.kind" names, after the <see cref="AimSolver"/> methods.</summary>
        public static readonly string[] Kinds =
        {
            "minimum-elevation-to-clear", "elevation-to-reach", "angles-to-reach", "speed-to-reach",
        };

        private const double DegreesToRadians = Math.PI / 180;

        /// <summary>Most elevation-scan trials one aim may ask for ((maximum - minimum elevation) / elevationScanDegrees): 10,000.</summary>
        public const int MaxScanTrials = 10_000;

        private sealed record AimRequest(string Name, string Path, AimSolver Solver, Vector3d Position, LaunchSpin Spin, Func<AimSolver, AimSolution> Solve, IReadOnlyList<string> Warnings);

        public static string Run(string json, TextWriter? warnings = null)
        {
            var requests = Read(json);
            var solutions = new List<(AimRequest Request, AimSolution Solution)>();
            foreach (AimRequest request in requests)
            {
                AimSolution solution;
                try
                {
                    solution = request.Solve(request.Solver);
                }
                catch (ArgumentException e)
                {
                    // The solver checks geometry the reader cannot (a target straight above the launch, a horizontal plane).
                    throw new InputError(request.Path + ".find", FirstSentence(e.Message));
                }

                solutions.Add((request, solution));
            }

            string output = Write(solutions);
            if (warnings != null)
            {
                // Only with a result, after every solve: an input error stays the one line on stderr.
                foreach (AimRequest request in requests)
                {
                    Program.WriteWarnings(warnings, request.Warnings);
                }
            }

            return output;
        }

        private static List<AimRequest> Read(string json)
        {
            using JsonDocument document = JsonInput.Parse(json);
            JsonFields root = JsonFields.Of(document.RootElement, string.Empty);
            JsonElement list = root.Required("aims");
            root.RejectUnknown();
            if (list.ValueKind != JsonValueKind.Array || list.GetArrayLength() == 0)
            {
                throw new InputError("aims", "must be a non-empty array of aim objects; got " + JsonFields.Describe(list));
            }

            var requests = new List<AimRequest>();
            int index = 0;
            foreach (JsonElement item in list.EnumerateArray())
            {
                requests.Add(ReadAim(JsonFields.Of(item, $"aims[{index}]"), index));
                index++;
            }

            return requests;
        }

        private static AimRequest ReadAim(JsonFields a, int index)
        {
            string name = a.String("name", $"aim-{index}");
            FlightSetup setup = ScenarioReader.ReadSetup(a);
            if (setup.Model.Up.LengthSquared == 0)
            {
                throw new InputError(a.PathOf("gravity"), "must not be zero for aiming (elevation is measured from the horizontal, up = -gravity)");
            }

            if (setup.Ground is not NamedPlane ground)
            {
                throw new InputError(a.PathOf("ground"), "must not be null for aiming (a trial that lands before its plane falls short)");
            }

            JsonFields launch = a.Object("launch");
            Vector3d position = launch.Vector("position");
            LaunchSpin spin = LaunchSpin.None;
            JsonFields? spinFields = launch.OptionalObject("spin");
            if (spinFields != null)
            {
                spin = new LaunchSpin(spinFields.Number("topspin", 0), spinFields.Number("sidespin", 0), spinFields.Number("gyro", 0));
                spinFields.RejectUnknown();
            }

            launch.RejectUnknown();

            JsonFields? limits = a.OptionalObject("limits");
            double minElevation = -45, maxElevation = 80, scan = 0.5, maxSpeed = 100;
            if (limits != null)
            {
                minElevation = InRange(limits, "minimumElevationDegrees", -45, -89, 89);
                maxElevation = InRange(limits, "maximumElevationDegrees", 80, -89, 89);
                if (!(maxElevation > minElevation))
                {
                    throw new InputError(limits.PathOf("maximumElevationDegrees"),
                        $"must be above minimumElevationDegrees ({JsonFields.Format(minElevation)}); got {JsonFields.Format(maxElevation)}");
                }

                scan = InRange(limits, "elevationScanDegrees", 0.5, 1e-6, 10);
                // The bracketing scan flies one trial per scan step: cap their number so no file can run unbounded.
                double trials = (maxElevation - minElevation) / scan;
                if (trials > MaxScanTrials)
                {
                    throw new InputError(limits.PathOf("elevationScanDegrees"),
                        $"the scan would fly {JsonFields.Format(Math.Ceiling(trials))} trial shots over [{JsonFields.Format(minElevation)}, {JsonFields.Format(maxElevation)}] deg; " +
                        $"at most {MaxScanTrials} are allowed: use a scan of at least {JsonFields.Format((maxElevation - minElevation) / MaxScanTrials)} deg or a narrower range");
                }
                maxSpeed = limits.Positive("maximumSpeed", 100);
                limits.RejectUnknown();
            }

            // Shapes are obstacles: a trial that touches one is not a solution, unless find names it as "viaShapeId" (a bank shot).
            IReadOnlyList<MagnusBall.Contact.Shapes.ContactShape> shapes = ScenarioShapes.Read(a, setup.Model.Up);
            var solver = new AimSolver(
                setup.Model, setup.Integrator, setup.Step, new Plane(ground.Point, ground.Normal), setup.MaxTime, minElevation, maxElevation, scan, maxSpeed,
                shapes: shapes.Count > 0 ? shapes.ToArray() : null);

            JsonFields find = a.Object("find");
            string kind = find.String("kind");
            Func<AimSolver, AimSolution> solve;
            double launchSpeed; // the fastest the request launches: the stability check below takes it
            switch (kind)
            {
                case "minimum-elevation-to-clear":
                {
                    double speed = launchSpeed = find.Positive("speed");
                    double azimuth = find.Number("azimuthDegrees", 0) * DegreesToRadians;
                    JsonFields planeFields = find.Object("plane");
                    var p = new Plane(planeFields.Vector("point"), planeFields.Direction("normal"));
                    planeFields.RejectUnknown();
                    double height = find.Number("height");
                    solve = s => s.MinimumElevationToClear(position, speed, azimuth, spin, p, height);
                    break;
                }

                case "elevation-to-reach":
                {
                    double speed = launchSpeed = find.Positive("speed");
                    Vector3d target = find.Vector("target");
                    double azimuth = find.Number("azimuthDegrees", 0) * DegreesToRadians;
                    int? via = ViaShapeId(find, shapes);
                    solve = s => s.ElevationToReach(position, speed, spin, target, azimuth, viaShapeId: via);
                    break;
                }

                case "angles-to-reach":
                {
                    double speed = launchSpeed = find.Positive("speed");
                    Vector3d target = find.Vector("target");
                    double maxAzimuth = InRange(find, "maximumAzimuthDegrees", 45, 1e-9, 89);
                    int? via = ViaShapeId(find, shapes);
                    solve = s => s.AnglesToReach(position, speed, spin, target, maxAzimuth, viaShapeId: via);
                    break;
                }

                case "speed-to-reach":
                {
                    double elevation = InRange(find, "elevationDegrees", double.NaN, -89.999, 89.999) * DegreesToRadians;
                    double azimuth = find.Number("azimuthDegrees", 0) * DegreesToRadians;
                    Vector3d target = find.Vector("target");
                    int? via = ViaShapeId(find, shapes);
                    solve = s => s.SpeedToReach(position, elevation, azimuth, spin, target, viaShapeId: via);
                    launchSpeed = maxSpeed;
                    break;
                }

                default:
                    throw new InputError(find.PathOf("kind"), $"unknown kind '{kind}'; expected one of: {string.Join(", ", Kinds)}");
            }

            find.RejectUnknown();
            a.RejectUnknown();

            // The trials fly the file's integrator at its step: a step beyond the method's stability bound at the
            // launch is refused, as simulate refuses it (its trials would diverge or fly a wrong path and the
            // solve would print "unreachable" for a target stable-rk4 reaches). The check takes the fastest launch
            // the request can make (speed-to-reach: maximumSpeed) into the wind, with the whole spin.
            // The unit-mistake warnings take the launch's speed (not speed-to-reach's search bound, which the user may leave at its default).
            FlightState fastest = FastestLaunch(setup.Model, position, launchSpeed, spin);
            StabilityCheck.Require(
                StabilityCheck.For(setup.Integrator), setup.Integrator, setup.Model, fastest, setup.Step, a.PathOf("step"));
            IReadOnlyList<string> warnings = SportWarnings.For(
                setup.Preset, setup.Model.Ball, kind == "speed-to-reach" ? 0 : launchSpeed, fastest.AngularVelocity.Length, a.PathOf("ball"),
                find.PathOf("speed"), launch.PathOf("spin"));
            return new AimRequest(name, a.Path, solver, position, spin, solve, warnings);
        }

        /// <summary>
        /// The launch with the largest air speed and spin the request can make: <paramref name="speed"/> straight into the
        /// wind (up where there is none), spinning at the spin's whole rate. The stiffness rate depends on the air
        /// speed and the spin rate, not on the directions (it takes the whole spin as transverse).
        /// </summary>
        private static FlightState FastestLaunch(FlightModel model, in Vector3d position, double speed, in LaunchSpin spin)
        {
            Vector3d wind = model.Air.WindAt(position, model.Up);
            Vector3d direction = wind.LengthSquared > 0 ? -wind.NormalizedOrZero() : model.Up;
            double rate = System.Math.Sqrt(spin.Topspin * spin.Topspin + spin.Sidespin * spin.Sidespin + spin.Gyro * spin.Gyro);
            Vector3d across = Vector3d.Cross(direction, System.Math.Abs(direction.X) < 0.9 ? Vector3d.UnitX : Vector3d.UnitY).NormalizedOrZero();
            return new FlightState(position, direction * speed, across * rate);
        }

        // A number in [min, max]; NaN as the fallback makes the field required.
        private static double InRange(JsonFields fields, string name, double fallback, double min, double max)
        {
            double value = double.IsNaN(fallback) ? fields.Number(name) : fields.Number(name, fallback);
            if (value < min || value > max)
            {
                throw new InputError(fields.PathOf(name), $"must be in [{JsonFields.Format(min)}, {JsonFields.Format(max)}]; got {JsonFields.Format(value)}");
            }

            return value;
        }

        // find's optional "viaShapeId": the id of one of the aim's shapes the ball must touch on its way (a bank shot).
        private static int? ViaShapeId(JsonFields find, IReadOnlyList<MagnusBall.Contact.Shapes.ContactShape> shapes)
        {
            if (!find.Has("viaShapeId"))
            {
                return null;
            }

            double value = find.Number("viaShapeId");
            if (!shapes.Any(shape => shape.Id == value))
            {
                string ids = shapes.Count == 0 ? "the aim has no shapes" : "the aim's shape ids are " + string.Join(", ", shapes.Select(shape => shape.Id).Distinct());
                throw new InputError(find.PathOf("viaShapeId"), $"must be the id of one of the aim's shapes ({ids}); got {JsonFields.Format(value)}");
            }

            return (int)value;
        }

        private static string Write(List<(AimRequest Request, AimSolution Solution)> solutions)
        {
            return JsonOutput.Write(w =>
            {
                w.WriteStartObject();
                w.WriteStartArray("results");
                foreach ((AimRequest request, AimSolution s) in solutions)
                {
                    w.WriteStartObject();
                    w.WriteString("name", request.Name);
                    w.WriteString("status", s.Status switch
                    {
                        AimStatus.Solved => "solved",
                        AimStatus.WorkLimitReached => "work-limit-reached",
                        AimStatus.Blocked => "blocked",
                        _ => "unreachable",
                    });
                    if (s.IsSolved)
                    {
                        w.WriteNumber("speed", s.Speed);
                        w.WriteNumber("elevationDegrees", s.ElevationDegrees);
                        w.WriteNumber("azimuthDegrees", s.AzimuthFromTargetDegrees);
                        WriteVector(w, "velocity", s.Velocity);
                        WriteVector(w, "angularVelocity", s.AngularVelocity);
                        w.WriteStartObject("arrival");
                        w.WriteNumber("time", s.Arrival.Time);
                        WriteVector(w, "position", s.Arrival.Position);
                        WriteVector(w, "velocity", s.Arrival.Velocity);
                        w.WriteEndObject();
                        // A clearance beyond what a double holds (a launch and a ground near 1e308 apart along up) is
                        // infinite in the library; JSON has no infinity, so it is written as the largest double.
                        w.WriteNumber("miss", Math.Clamp(s.Miss, -double.MaxValue, double.MaxValue));
                    }

                    w.WriteNumber("simulations", s.Simulations);
                    w.WriteEndObject();
                }

                w.WriteEndArray();
                w.WriteEndObject();
            });
        }

        private static void WriteVector(Utf8JsonWriter w, string name, Vector3d v)
        {
            w.WriteStartArray(name);
            w.WriteNumberValue(v.X);
            w.WriteNumberValue(v.Y);
            w.WriteNumberValue(v.Z);
            w.WriteEndArray();
        }

        private static string FirstSentence(string message)
        {
            int cut = message.IndexOf(" (Parameter '", StringComparison.Ordinal);
            return (cut > 0 ? message.Substring(0, cut) : message).TrimEnd('.');
        }
    }
}
