using System;
using System.Collections.Generic;
using System.Linq;
using System.Text.Json;
using MagnusBall.Aerodynamics;
using MagnusBall.Integration;
using MagnusBall.Presets;

namespace MagnusBall.Cli
{
    /// <summary>
    /// Reads the scenario format of issue 3 (docs/cli.md) into checked <see cref="Scenario"/>s. Every field
    /// is checked before anything is simulated; the first bad field throws an <see cref="InputError"/>
    /// naming it by its JSON path. Unknown and duplicated fields are errors, so typos do not pass silently.
    /// </summary>
    internal static class ScenarioReader
    {
        /// <summary>Default air density when "air" or "air.density" is absent: ISA sea level, 1.225 kg/m^3.</summary>
        public const double DefaultDensity = Air.SeaLevelDensity;

        /// <summary>Default step when "step" is absent: 1/240 s.</summary>
        public const double DefaultStep = 1.0 / 240;

        /// <summary>Default time limit when "maxTime" is absent: 10 s.</summary>
        public const double DefaultMaxTime = 10;

        /// <summary>Default integrator when "integrator" is absent.</summary>
        public const string DefaultIntegrator = "rk4";

        /// <summary>Most steps one scenario may ask for (maxTime / step), so a typo cannot hang the tool.</summary>
        public const double MaxSteps = 1e7;

        /// <summary>Default gravity when "gravity" is absent: standard gravity along -z (a z-up frame).</summary>
        public static Vector3d DefaultGravity => Gravity.ZUp;

        public static IReadOnlyList<Scenario> Read(string json)
        {
            using JsonDocument document = JsonInput.Parse(json);
            JsonFields root = JsonFields.Of(document.RootElement, string.Empty);
            if (document.RootElement.ValueKind == JsonValueKind.Object && !root.Has("scenarios") && root.Has("aims"))
            {
                throw new InputError("scenarios", "required field is missing; this file has \"aims\": it is an aim file, run it with 'magnusball aim FILE'");
            }

            JsonElement list = root.Required("scenarios");
            root.RejectUnknown();
            if (list.ValueKind != JsonValueKind.Array)
            {
                throw new InputError("scenarios", "must be an array of scenario objects; got " + JsonFields.Describe(list));
            }

            if (list.GetArrayLength() == 0)
            {
                throw new InputError("scenarios", "must hold at least one scenario; got an empty array");
            }

            var scenarios = new List<Scenario>();
            int index = 0;
            foreach (JsonElement item in list.EnumerateArray())
            {
                scenarios.Add(ReadScenario(JsonFields.Of(item, $"scenarios[{index}]"), index));
                index++;
            }

            return scenarios;
        }

        private static Scenario ReadScenario(JsonFields s, int index)
        {
            string name = s.String("name", $"scenario-{index}");
            FlightSetup setup = ReadSetup(s);

            JsonFields initialFields = s.Object("initial");
            var initial = new FlightState(
                initialFields.Vector("position"),
                initialFields.Vector("velocity"),
                initialFields.Vector("angularVelocity", Vector3d.Zero),
                initialFields.Number("time", 0));
            initialFields.RejectUnknown();
            CheckTimeAdvances(initial.Time, setup, initialFields.PathOf("time"));

            var planes = new List<NamedPlane>();
            JsonElement? planeList = s.Optional("planes");
            if (planeList.HasValue)
            {
                if (planeList.Value.ValueKind != JsonValueKind.Array)
                {
                    throw new InputError(s.PathOf("planes"), "must be an array of plane objects; got " + JsonFields.Describe(planeList.Value));
                }

                int i = 0;
                foreach (JsonElement item in planeList.Value.EnumerateArray())
                {
                    JsonFields planeFields = JsonFields.Of(item, $"{s.PathOf("planes")}[{i}]");
                    planes.Add(ReadPlane(planeFields, planeFields.String("name"), setup.Model.Up, allowName: true));
                    i++;
                }
            }

            IReadOnlyList<MagnusBall.Contact.Shapes.ContactShape> shapes = ScenarioShapes.Read(s, setup.Model.Up);
            s.RejectUnknown();
            IReadOnlyList<string> warnings = SportWarnings.For(
                setup.Preset, setup.Model.Ball, initial.Velocity.Length, initial.AngularVelocity.Length,
                s.PathOf("ball"), initialFields.PathOf("velocity"), initialFields.PathOf("angularVelocity"));
            return new Scenario(index, name, setup.Model, initial, setup.Integrator, setup.Step, setup.Ground, planes, setup.MaxTime, warnings, shapes);
        }

        /// <summary>
        /// Time must be able to advance by a step everywhere in the flight: a double resolves time to one ulp of it
        /// (0.125 s at t = 1e15 s), so the step must be at least <see cref="MinimumStepInUlps"/> ulps of the latest
        /// |time| the flight can reach, or each step would be rounded away or badly distorted.
        /// </summary>
        internal static void CheckTimeAdvances(double time, FlightSetup setup, string path)
        {
            double latest = Math.Max(Math.Abs(time), Math.Abs(time + setup.MaxTime));
            if (!double.IsFinite(latest))
            {
                // time + maxTime overflows (the message below would say "at |t| = Infinity s a double resolves only NaN s").
                throw new InputError(path,
                    $"time cannot advance: the flight would end past the largest double (t = {JsonFields.Format(time)} s plus maxTime {JsonFields.Format(setup.MaxTime)} s); start the flight nearer t = 0");
            }

            double ulp = Math.BitIncrement(latest) - latest;
            if (!(ulp * MinimumStepInUlps <= setup.Step))
            {
                throw new InputError(path,
                    $"time cannot advance: at |t| = {JsonFields.Format(latest)} s a double resolves only {JsonFields.Format(ulp)} s, " +
                    $"so a step of {JsonFields.Format(setup.Step)} s (less than {MinimumStepInUlps} times that) would be rounded away or distorted; start the flight nearer t = 0");
            }
        }

        /// <summary>The step must span at least this many ulps of the flight's latest time (see <see cref="CheckTimeAdvances"/>).</summary>
        public const double MinimumStepInUlps = 1024;

        /// <summary>
        /// Reads the fields a scenario and an aim share: ball, air, gravity, aero, spinDecay, integrator, step,
        /// maxTime and ground. The caller reads its own fields and then calls <see cref="JsonFields.RejectUnknown"/>.
        /// </summary>
        internal static FlightSetup ReadSetup(JsonFields s)
        {
            // "preset" (issue 7) supplies the ball, aero and spin decay; explicit fields override each part.
            SportPreset? preset = PresetAndAirFields.ReadPreset(s);
            Ball ball = PresetAndAirFields.ReadBall(s, preset);
            Air air = PresetAndAirFields.ReadAir(s, DefaultDensity);

            Vector3d gravity = s.Vector("gravity", DefaultGravity);

            IDragModel? drag = preset?.Drag;
            ILiftModel? lift = preset?.Lift;
            JsonFields? aero = s.OptionalObject("aero");
            if (aero != null)
            {
                // Without a preset an absent law is off, as before; with one, only a given law replaces it.
                if (preset is null || aero.Has("drag"))
                {
                    drag = ReadDrag(aero.OptionalObject("drag"));
                }

                if (preset is null || aero.Has("lift"))
                {
                    lift = ReadLift(aero.OptionalObject("lift"));
                }

                aero.RejectUnknown();
            }

            ISpinDecayModel? spinDecay = preset != null && !s.Has("spinDecay")
                ? preset.SpinDecay
                : ReadSpinDecay(s.OptionalObject("spinDecay"));

            IIntegrator integrator = ReadIntegrator(s);
            double step = s.Positive("step", DefaultStep);
            double maxTime = s.Positive("maxTime", DefaultMaxTime);
            if (maxTime / step > MaxSteps)
            {
                throw new InputError(s.PathOf("maxTime"),
                    $"maxTime / step must be at most {MaxSteps:0e0} steps; got {JsonFields.Format(maxTime)} s / {JsonFields.Format(step)} s");
            }

            var model = new FlightModel(ball, air, gravity, drag, lift, spinDecay);
            Vector3d up = model.Up;

            NamedPlane? ground;
            if (s.IsNull("ground"))
            {
                ground = null; // "ground": null switches the ground off.
            }
            else
            {
                JsonFields? groundFields = s.OptionalObject("ground");
                if (groundFields is null)
                {
                    ground = up.LengthSquared > 0 ? new NamedPlane("ground", Vector3d.Zero, up, null) : null;
                }
                else
                {
                    ground = ReadPlane(groundFields, "ground", up, allowName: false);
                }
            }

            return new FlightSetup(model, integrator, step, ground, maxTime, preset);
        }

        /// <summary>
        /// The integrator names a scenario accepts: every name <see cref="Integrators.FromName"/> knows (the four
        /// classic methods, "dp54" at a fixed step and the safe "stable-rk4").
        /// </summary>
        public static IReadOnlyList<string> IntegratorNames => Integrators.Names;

        private static IIntegrator ReadIntegrator(JsonFields s)
        {
            string name = s.String("integrator", DefaultIntegrator);
            try
            {
                return Integrators.FromName(name);
            }
            catch (ArgumentException)
            {
                throw new InputError(s.PathOf("integrator"),
                    $"unknown integrator '{name}'; expected one of: {string.Join(", ", IntegratorNames)}");
            }
        }

        private static string ReadModelName(JsonFields fields, params string[] known)
        {
            string model = fields.String("model");
            foreach (string k in known)
            {
                if (string.Equals(k, model, StringComparison.OrdinalIgnoreCase))
                {
                    return k;
                }
            }

            throw new InputError(fields.PathOf("model"), $"unknown model '{model}'; expected one of: {string.Join(", ", known)}");
        }

        private static IDragModel? ReadDrag(JsonFields? fields)
        {
            if (fields is null)
            {
                return null;
            }

            IDragModel? drag = ReadModelName(fields, "none", "constant", "stepanek", "linear-spin", "goff-carre", "nathan") switch
            {
                "constant" => new ConstantDrag(fields.NonNegativeRequired("cd")),
                "stepanek" => StepanekDrag.Instance,
                "linear-spin" => new LinearSpinDrag(fields.NonNegativeRequired("cd0"), fields.NonNegativeRequired("k")),
                "goff-carre" => GoffCarreSoccerDrag.Instance,
                "nathan" => NathanBaseballDrag.Instance,
                _ => null,
            };
            fields.RejectUnknown();
            return drag;
        }

        private static ILiftModel? ReadLift(JsonFields? fields)
        {
            if (fields is null)
            {
                return null;
            }

            ILiftModel? lift = ReadModelName(fields, "none", "constant", "stepanek", "linear-spin", "goff-carre", "nathan", "smits-smith-golf", "table") switch
            {
                "smits-smith-golf" => PiecewiseLinearLift.GolfSmitsSmith,
                "table" => PresetAndAirFields.ReadLiftTable(fields),
                "constant" => new ConstantLift(fields.Number("cl")),
                "stepanek" => StepanekLift.Instance,
                "linear-spin" => new LinearSpinLift(fields.Number("k")),
                "goff-carre" => PiecewiseLinearLift.SoccerGoffCarre,
                "nathan" => NathanBaseballLift.Instance,
                _ => null,
            };
            fields.RejectUnknown();
            return lift;
        }

        private static ISpinDecayModel? ReadSpinDecay(JsonFields? fields)
        {
            if (fields is null)
            {
                return null;
            }

            ISpinDecayModel? decay = ReadModelName(fields, "none", "exponential", "speed-proportional") switch
            {
                "exponential" => new ExponentialSpinDecay(fields.Positive("tau")),
                "speed-proportional" => new SpeedProportionalSpinDecay(fields.NonNegativeRequired("k")),
                _ => null,
            };
            fields.RejectUnknown();
            return decay;
        }

        internal static NamedPlane ReadPlane(JsonFields fields, string name, Vector3d up, bool allowName)
        {
            if (allowName && name.Length == 0)
            {
                throw new InputError(fields.PathOf("name"), "must not be empty");
            }

            Vector3d point = fields.Vector("point", Vector3d.Zero);
            Vector3d normal;
            if (allowName || fields.Has("normal"))
            {
                normal = fields.Direction("normal");
            }
            else if (up.LengthSquared > 0)
            {
                normal = up; // The ground's normal defaults to up (-gravity).
            }
            else
            {
                throw new InputError(fields.PathOf("normal"), "required field is missing (gravity is zero, so there is no default up)");
            }

            if (allowName && !fields.Has("point"))
            {
                throw new InputError(fields.PathOf("point"), "required field is missing");
            }

            normal = normal.NormalizedOrZero();
            PlaneBounds? bounds = ReadBounds(fields.OptionalObject("bounds"), normal, up);
            fields.RejectUnknown();
            return new NamedPlane(name, point, normal, bounds);
        }

        private static PlaneBounds? ReadBounds(JsonFields? fields, Vector3d normal, Vector3d up)
        {
            if (fields is null)
            {
                return null;
            }

            // The plane's height axis is "up" projected onto the plane; width is normal x height.
            Vector3d heightAxis = (up - normal * Vector3d.Dot(up, normal)).NormalizedOrZero();
            if (!(heightAxis.Length > 0.5))
            {
                throw new InputError(fields.Path, "a plane with bounds must not be horizontal (its height axis is up projected onto the plane)");
            }

            Vector3d widthAxis = Vector3d.Cross(normal, heightAxis);
            (double hMin, double hMax) = ReadRange(fields, "height");
            (double wMin, double wMax) = ReadRange(fields, "width");
            fields.RejectUnknown();
            return new PlaneBounds(heightAxis, widthAxis, hMin, hMax, wMin, wMax);
        }

        private static (double Min, double Max) ReadRange(JsonFields fields, string name)
        {
            JsonElement? value = fields.Optional(name);
            if (!value.HasValue)
            {
                return (double.NegativeInfinity, double.PositiveInfinity);
            }

            string path = fields.PathOf(name);
            if (value.Value.ValueKind != JsonValueKind.Array || value.Value.GetArrayLength() != 2)
            {
                throw new InputError(path, "must be an array of 2 finite numbers [min, max]; got " + JsonFields.Describe(value.Value));
            }

            double min = JsonFields.ReadNumber(value.Value[0], path + "[0]");
            double max = JsonFields.ReadNumber(value.Value[1], path + "[1]");
            if (min > max)
            {
                throw new InputError(path, $"min must not exceed max; got [{JsonFields.Format(min)}, {JsonFields.Format(max)}]");
            }

            return (min, max);
        }
    }
}
