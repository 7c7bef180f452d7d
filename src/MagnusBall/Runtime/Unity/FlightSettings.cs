#nullable enable
using System;
using MagnusBall.Aerodynamics;
using MagnusBall.Contact;
using MagnusBall.Integration;
using MagnusBall.Presets;

namespace MagnusBall.Components
{
    /// <summary>Which integrator steps the ball (an inspector drop-down).</summary>
    public enum IntegratorChoice
    {
        /// <summary>Classic RK4 (fourth order): the default.</summary>
        RungeKutta4 = 0,

        /// <summary>RK4 with stability-safe substeps (StableIntegrator): for long fixed steps with light, fast balls.</summary>
        StableRungeKutta4 = 1,

        /// <summary>Heun / RK2 (second order).</summary>
        Heun = 2,

        /// <summary>Semi-implicit Euler (first order; what PhysX does).</summary>
        SemiImplicitEuler = 3,

        /// <summary>Explicit Euler (first order).</summary>
        Euler = 4,
    }

    /// <summary>What the ball bounces on (an inspector drop-down).</summary>
    public enum SurfaceChoice
    {
        /// <summary>The preset's own bounce (tennis: a hard court); none if the preset has none.</summary>
        Preset = 0,

        /// <summary>No bounce: the flight ends where the ball first comes down.</summary>
        None = 1,

        /// <summary>Cross's slide/grip bounce on a hard court.</summary>
        Hard = 2,

        /// <summary>Cross's bounce on clay.</summary>
        Clay = 3,

        /// <summary>Cross's bounce on grass.</summary>
        Grass = 4,
    }

    /// <summary>A preset of <see cref="SportPresets"/> (an inspector drop-down; <see cref="FlightSettings.PresetName"/> gives its name).</summary>
    public enum PresetChoice
    {
        /// <summary>"tennis": Stepanek's drag and lift, spin decay, Cross's hard-court bounce.</summary>
        Tennis = 0,

        /// <summary>"tennis-free-flight": the tennis ball without spin decay.</summary>
        TennisFreeFlight = 1,

        /// <summary>"soccer".</summary>
        Soccer = 2,

        /// <summary>"baseball".</summary>
        Baseball = 3,

        /// <summary>"golf".</summary>
        Golf = 4,

        /// <summary>"golf-smits-smith".</summary>
        GolfSmitsSmith = 5,

        /// <summary>"table-tennis".</summary>
        TableTennis = 6,

        /// <summary>"basketball".</summary>
        Basketball = 7,

        /// <summary>"golf-bearman-harvey".</summary>
        GolfBearmanHarvey = 8,

        /// <summary>"golf-linear-2023".</summary>
        GolfLinear2023 = 9,
    }

    /// <summary>
    /// The ball, its aerodynamics and the air, as the inspector shows them: a preset picked from a drop-down
    /// (<see cref="presetChoice"/>), optionally with its ball or its drag and lift replaced by constants. Shared by the
    /// package's components.
    /// </summary>
    /// <remarks>
    /// Before 0.2.0 the preset was a free-text field <c>preset</c>. A scene or prefab saved then still loads: the old
    /// text is read into a hidden field (<c>[FormerlySerializedAs("preset")]</c>) and turned into the drop-down's value
    /// after loading (<c>ISerializationCallbackReceiver.OnAfterDeserialize</c>). A name no preset has leaves the drop-down
    /// empty (a value outside the enum) and is refused by <see cref="Preset"/>, naming <c>preset</c> and the old text,
    /// until a preset is picked; the old text is dropped at the next save after that.
    /// </remarks>
    [Serializable]
    public sealed class FlightSettings : UnityEngine.ISerializationCallbackReceiver
    {
        /// <summary>The preset these settings start from.</summary>
        [UnityEngine.Tooltip("The ball and its aerodynamics: tennis, soccer, baseball, golf (four lift laws), table tennis, basketball.")]
        public PresetChoice presetChoice = PresetChoice.Tennis;

        // The old free-text field's value from a scene saved before 0.2.0, until it is migrated (or refused, when unknown).
        [UnityEngine.SerializeField]
        [UnityEngine.HideInInspector]
        [UnityEngine.Serialization.FormerlySerializedAs("preset")]
        private string legacyPresetName = string.Empty;

        /// <summary>
        /// The preset's name (see <see cref="SportPresets.Names"/>), for code written before the drop-down: reading gives
        /// the name of <see cref="presetChoice"/>, setting picks the preset of that name (as <see cref="SportPresets.FromName"/>
        /// reads it: case-insensitive, '_' or ' ' for '-').
        /// </summary>
        /// <exception cref="ArgumentException">Set to null or a name no preset has (the message lists the names); nothing changes.</exception>
        public string preset
        {
            get => IsChoice(presetChoice) ? PresetName(presetChoice) : legacyPresetName;
            set
            {
                presetChoice = ParsePreset(value, nameof(preset));
                legacyPresetName = string.Empty;
            }
        }

        /// <summary>The name <see cref="SportPresets.FromName"/> knows a choice by.</summary>
        /// <param name="choice">The drop-down's value.</param>
        /// <exception cref="ArgumentException">The value is not one of <see cref="PresetChoice"/>'s.</exception>
        public static string PresetName(PresetChoice choice)
        {
            switch (choice)
            {
                case PresetChoice.Tennis: return "tennis";
                case PresetChoice.TennisFreeFlight: return "tennis-free-flight";
                case PresetChoice.Soccer: return "soccer";
                case PresetChoice.Baseball: return "baseball";
                case PresetChoice.Golf: return "golf";
                case PresetChoice.GolfSmitsSmith: return "golf-smits-smith";
                case PresetChoice.TableTennis: return "table-tennis";
                case PresetChoice.Basketball: return "basketball";
                case PresetChoice.GolfBearmanHarvey: return "golf-bearman-harvey";
                case PresetChoice.GolfLinear2023: return "golf-linear-2023";
                default:
                    throw new ArgumentOutOfRangeException(nameof(choice), choice, "choice must be one of PresetChoice's values (0-9).");
            }
        }

        // A preset's name as the drop-down's value; refused naming `field`, with the names listed.
        private static PresetChoice ParsePreset(string name, string field)
        {
            SportPreset found = Field(field, () => SportPresets.FromName(name));
            foreach (PresetChoice choice in (PresetChoice[])Enum.GetValues(typeof(PresetChoice)))
            {
                if (PresetName(choice) == found.Name)
                {
                    return choice;
                }
            }

            throw new ArgumentException($"{field}: the preset '{found.Name}' has no entry in the drop-down (PresetChoice).", field);
        }

        /// <summary>Before Unity saves: an old preset name is dropped once the drop-down has a value.</summary>
        void UnityEngine.ISerializationCallbackReceiver.OnBeforeSerialize()
        {
            if (IsChoice(presetChoice))
            {
                legacyPresetName = string.Empty;
            }
        }

        private static bool IsChoice(PresetChoice choice) => choice >= PresetChoice.Tennis && choice <= PresetChoice.GolfLinear2023;

        /// <summary>After Unity loads: an old free-text preset name becomes the drop-down's value (an unknown one is kept, and refused when used).</summary>
        void UnityEngine.ISerializationCallbackReceiver.OnAfterDeserialize()
        {
            if (string.IsNullOrEmpty(legacyPresetName))
            {
                legacyPresetName = string.Empty;
                return;
            }

            try
            {
                presetChoice = ParsePreset(legacyPresetName, nameof(preset));
                legacyPresetName = string.Empty;
            }
            catch (ArgumentException)
            {
                presetChoice = (PresetChoice)(-1); // the drop-down shows no value; Preset() refuses the old name until one is picked
            }
        }

        /// <summary>Replace the preset's ball by <see cref="mass"/>, <see cref="radius"/> and <see cref="inertiaFactor"/>.</summary>
        [UnityEngine.Tooltip("Use the mass, radius and inertia factor below instead of the preset's ball.")]
        public bool customBall;

        /// <summary>Ball mass, kg (with <see cref="customBall"/>).</summary>
        [UnityEngine.Tooltip("kg")]
        [UnityEngine.Min(0.0001f)]
        public float mass = 0.057f;

        /// <summary>Ball radius, m (with <see cref="customBall"/>).</summary>
        [UnityEngine.Tooltip("m")]
        [UnityEngine.Min(0.0001f)]
        public float radius = 0.033f;

        /// <summary>Moment of inertia over m r^2 (with <see cref="customBall"/>): 0.4 solid, 2/3 thin shell, 0.55 tennis.</summary>
        [UnityEngine.Tooltip("I / (m r^2): 0.4 solid sphere, 0.667 thin shell, 0.55 tennis ball.")]
        [UnityEngine.Range(0.01f, 1f)]
        public float inertiaFactor = 0.55f;

        /// <summary>Replace the preset's drag and lift laws by the constants <see cref="dragCoefficient"/> and <see cref="liftCoefficient"/>.</summary>
        [UnityEngine.Tooltip("Use the constant C_D and C_L below instead of the preset's laws.")]
        public bool constantCoefficients;

        /// <summary>Constant drag coefficient C_D (with <see cref="constantCoefficients"/>).</summary>
        [UnityEngine.Tooltip("C_D (the thesis's tennis ball: 0.55)")]
        [UnityEngine.Range(0f, 2f)]
        public float dragCoefficient = 0.55f;

        /// <summary>Constant lift (Magnus) coefficient C_L (with <see cref="constantCoefficients"/>).</summary>
        [UnityEngine.Tooltip("C_L (the thesis's tennis ball: 0.175)")]
        [UnityEngine.Range(-1f, 1f)]
        public float liftCoefficient = 0.175f;

        /// <summary>Air density, kg/m^3 (sea level 1.225; Cross's tennis measurements 1.21).</summary>
        [UnityEngine.Tooltip("kg/m^3 (sea level: 1.225)")]
        [UnityEngine.Min(0f)]
        public float airDensity = (float)Air.SeaLevel.Density;

        /// <summary>What the ball bounces on.</summary>
        [UnityEngine.Tooltip("The bounce: the preset's, none, or Cross's model on a hard, clay or grass court.")]
        public SurfaceChoice surface = SurfaceChoice.Preset;

        /// <summary>The preset these settings start from.</summary>
        /// <exception cref="ArgumentException">An old scene's <see cref="preset"/> name is unknown (the message lists the names), or the custom ball or constants are out of range.</exception>
        public SportPreset Preset()
        {
            if (!IsChoice(presetChoice))
            {
                throw legacyPresetName.Length > 0
                    ? new ArgumentException(
                        $"preset: '{legacyPresetName}' (saved by an older version) is no preset; pick one from the drop-down (one of: {string.Join(", ", SportPresets.Names)}).",
                        nameof(preset))
                    : new ArgumentException($"presetChoice must be one of PresetChoice's values (0-9); got {(int)presetChoice}.", nameof(presetChoice));
            }

            SportPreset chosen = SportPresets.FromName(PresetName(presetChoice));
            if (customBall)
            {
                chosen = chosen.WithBall(new Ball(mass, radius, inertiaFactor));
            }

            if (constantCoefficients)
            {
                chosen = chosen.WithDrag(new ConstantDrag(dragCoefficient)).WithLift(new ConstantLift(liftCoefficient));
            }

            return chosen;
        }

        /// <summary>The flight model in Unity's world: these settings under <paramref name="gravity"/>.</summary>
        /// <param name="gravity">Gravity, m/s^2 (usually <see cref="Gravity.YUp"/>).</param>
        /// <exception cref="ArgumentException">A setting is out of range (the message names it).</exception>
        public FlightModel CreateModel(Vector3d gravity)
        {
            SportPreset chosen = Preset();
            Air air = Field(nameof(airDensity), () => new Air(airDensity));
            return chosen.CreateModel(air, gravity);
        }

        // An inspector field's value through a library constructor: its refusal named by the field, not the constructor's
        // parameter ("airDensity", not "density"). Configuration time only (the delegate is not per frame).
        internal static T Field<T>(string field, Func<T> make)
        {
            try
            {
                return make();
            }
            catch (ArgumentException e) when (e.ParamName != field)
            {
                throw new ArgumentException($"{field} (the inspector field): {e.Message}", field, e);
            }
        }

        /// <summary>The bounce model <see cref="surface"/> selects, or null for none.</summary>
        public IBounceModel? CreateBounce()
        {
            switch (surface)
            {
                case SurfaceChoice.None: return null;
                case SurfaceChoice.Hard: return CrossBounce.Hard;
                case SurfaceChoice.Clay: return CrossBounce.Clay;
                case SurfaceChoice.Grass: return new CrossBounce(Surface.Grass);
                default: return Preset().Bounce;
            }
        }

        /// <summary>The integrator for a choice.</summary>
        /// <param name="choice">The inspector's choice.</param>
        public static IIntegrator Integrator(IntegratorChoice choice)
        {
            switch (choice)
            {
                case IntegratorChoice.Euler: return ExplicitEuler.Instance;
                case IntegratorChoice.SemiImplicitEuler: return SemiImplicitEuler.Instance;
                case IntegratorChoice.Heun: return Heun.Instance;
                case IntegratorChoice.StableRungeKutta4: return StableIntegrator.RungeKutta4;
                default: return RungeKutta4.Instance;
            }
        }
    }
}
