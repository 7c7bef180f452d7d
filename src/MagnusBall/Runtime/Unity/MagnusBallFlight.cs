#nullable enable
using System;
using System.Collections.Generic;
using MagnusBall.Flight;
using MagnusBall.Contact;
using MagnusBall.Contact.Shapes;
using MagnusBall.Integration;
using MagnusBall.Queries;
using MagnusBall.Stepping;
using UnityEngine;
using UnityEngine.Events;

namespace MagnusBall.Components
{
    /// <summary>Where a component takes its fixed steps.</summary>
    public enum StepIn
    {
        /// <summary>In <c>Update</c>, from <c>Time.deltaTime</c>; the transform shows the interpolated render state.</summary>
        Update = 0,

        /// <summary>In <c>FixedUpdate</c>, from <c>Time.fixedDeltaTime</c>; the transform shows the latest fixed state.</summary>
        FixedUpdate = 1,
    }

    /// <summary>
    /// Flies the GameObject's transform as a spinning ball: gravity, drag and the Magnus force from MagnusBall,
    /// stepped at a fixed step by a <see cref="FixedStepDriver"/> (the same landing at any frame rate), with
    /// events for the landing, each bounce, each crossing of a watched plane (a net), the apex and the stop.
    /// No Rigidbody: the spin lives in the library's state, never in Unity's clipped angularVelocity.
    /// </summary>
    /// <remarks>
    /// <para>Add it to a GameObject (a sphere of the ball's size), pick a preset or a custom ball in the
    /// inspector and call <see cref="Launch(Vector3, Vector3)"/> or <see cref="Launch(Vector3, float, float)"/>
    /// from a script. The ball flies from the transform's position. Code can replace the inspector's model,
    /// integrator, events and bounce with <see cref="Configure"/>.</para>
    /// <para>Unity's world is y-up and left-handed; the library runs in it unchanged (see <see cref="UnityFrame"/>),
    /// with gravity <see cref="Gravity.YUp"/>. The ground is the plane y = <see cref="groundHeight"/>; the ball
    /// touches it when its centre is one radius above.</para>
    /// <para>Events are raised from inside <c>Update</c> (or <c>FixedUpdate</c>), once each (every one: the event buffer
    /// holds any step's, and a frame with more is finished after they are raised), in time order,
    /// with their exact time and state (located inside the step; they may lie up to one fixed step after
    /// what is drawn). Each is raised twice over: the C# event (<see cref="Landed"/>, ...) first, then the inspector's
    /// UnityEvent (<see cref="onLanded"/>, ...). Nothing allocates per frame after the launch.</para>
    /// <para>Inspector edits take effect at once, also during Play (<c>OnValidate</c>): the next launch uses them, and a
    /// ball in flight flies on under them from where it is. A value the launch would refuse is refused the same way and
    /// reported once in the Console, naming the field; the previous settings stay in use. Selected, the component draws
    /// the current arc, the ground and the watched plane in the Scene view.</para>
    /// </remarks>
    [AddComponentMenu("MagnusBall/Ball Flight")]
    [DisallowMultipleComponent]
    [HelpURL(UnityFrame.ManualUrl + "#ball-flight")]
    public partial class MagnusBallFlight : MonoBehaviour
    {
        /// <summary>The ball, its aerodynamics, the air and the bounce.</summary>
        public FlightSettings settings = new FlightSettings();

        /// <summary>The integrator.</summary>
        [Header("Stepping")]
        [Tooltip("RK4 is accurate to micrometres at 1/240 s; semi-implicit Euler is what PhysX does.")]
        public IntegratorChoice integrator = IntegratorChoice.RungeKutta4;

        /// <summary>The fixed step, s.</summary>
        [Tooltip("Fixed step, s. The flight is the same at any frame rate for a given step.")]
        [Min(0.0001f)]
        public float fixedStep = 1f / 240f;

        /// <summary>Frame-time clamp, s: a longer frame (a hitch) is cut to this.</summary>
        [Tooltip("Frame-time clamp, s: a longer frame (a hitch) is cut to this. At least the fixed step.")]
        [Min(0.001f)]
        public float maxFrameDelta = (float)FixedStepDriver.DefaultMaxFrameDeltaSeconds;

        /// <summary>Step in Update (interpolated drawing) or in FixedUpdate.</summary>
        [Tooltip("Update: from Time.deltaTime, drawn interpolated. FixedUpdate: from Time.fixedDeltaTime, drawn at the fixed state.")]
        public StepIn stepIn = StepIn.Update;

        /// <summary>Height of the ground plane, m (the court's surface, not the ball's centre).</summary>
        [Header("World")]
        [Tooltip("y of the ground, m. The ball lands when its bottom touches it.")]
        public float groundHeight;

        /// <summary>Watch a plane (a net) and raise <see cref="PlaneCrossed"/> when the ball's centre crosses it along its normal.</summary>
        [Tooltip("Raise PlaneCrossed when the ball's centre crosses this plane along its normal (a net).")]
        public bool watchPlane;

        /// <summary>A point of the watched plane, m.</summary>
        public Vector3 planePoint = Vector3.zero;

        /// <summary>The watched plane's normal (need not be unit length).</summary>
        public Vector3 planeNormal = new Vector3(1, 0, 0);

        /// <summary>
        /// The scene's colliders the ball hits in flight (walls, boards, posts): each becomes a MagnusBall contact shape where the
        /// match is exact (BoxCollider: a box, CapsuleCollider: a capsule, SphereCollider: a sphere; see <see cref="ColliderShapes"/>), with id its index
        /// here; others are skipped with a warning. Read at <see cref="ApplySettings"/>: move a collider, apply again.
        /// </summary>
        [Tooltip("Colliders the ball hits in flight: boxes, capsules and spheres become exact MagnusBall shapes (id = index); others are skipped with a warning.")]
        public List<Collider> shapeColliders = new List<Collider>();

        /// <summary>The normal restitution of a hit on a collider's shape, in [0, 1].</summary>
        [Tooltip("Normal restitution of a hit on those colliders, 0..1.")]
        [Range(0, 1)]
        public float shapeRestitution = 0.7f;

        /// <summary>The friction of a hit on a collider's shape, &gt;= 0.</summary>
        [Tooltip("Friction of a hit on those colliders, >= 0.")]
        public float shapeFriction = 0.3f;

        /// <summary>Turn the transform with the ball's spin (for the eye; the physics does not need it).</summary>
        [Tooltip("Turn the transform with the ball's spin.")]
        public bool rotateWithSpin = true;

        /// <summary>Raised at every launch, after <see cref="Launched"/> (the ball is at its start).</summary>
        [Header("Events (raised after the C# events of the same name)")]
        public UnityEvent onLaunched = new UnityEvent();

        /// <summary>Raised with <see cref="Landed"/>: the ball came down and, without a bounce model, the flight ended there.</summary>
        public FlightEventUnityEvent onLanded = new FlightEventUnityEvent();

        /// <summary>Raised with <see cref="Bounced"/>.</summary>
        public FlightEventUnityEvent onBounced = new FlightEventUnityEvent();

        /// <summary>Raised with <see cref="PlaneCrossed"/>: the ball's centre crossed the watched plane.</summary>
        public FlightEventUnityEvent onPlaneCrossed = new FlightEventUnityEvent();

        /// <summary>Raised with <see cref="ApexReached"/>.</summary>
        public FlightEventUnityEvent onApex = new FlightEventUnityEvent();

        /// <summary>Raised with <see cref="Stopped"/>: the ball came to rest.</summary>
        public FlightEventUnityEvent onStopped = new FlightEventUnityEvent();

        /// <summary>Raised with <see cref="Contacted"/>: the ball hit one of the shapes (its ShapeId: the index in shapeColliders).</summary>
        public FlightEventUnityEvent onContact = new FlightEventUnityEvent();

        private FlightEvent[] _events = new FlightEvent[16]; // grown at a launch to the driver's MaximumEventsPerStep: no event is lost
        private FlightModel? _model;
        private IIntegrator? _integrator;
        private FlightEventSet? _eventSet;
        private IBounceModel? _bounce;
        private ContactShape[]? _shapes;

        /// <summary>The contact shapes the ball's flights meet (from shapeColliders or Configure), or null: the preview predicts with them.</summary>
        internal ContactShape[]? Shapes => _shapes;
        private double _fixedStep;
        private double _maxFrameDelta;
        private FixedStepDriver? _driver;
        private bool _flying;
        private FlightState _segmentStart;
        private int _segmentVersion;
        private bool _configuredInCode; // Configure or Launch(start, model, ...) set the configuration: inspector edits do not replace it
        private string? _reported; // the last inspector problem reported, so that each is reported once
        private Vector3d[]? _gizmoPath;

        /// <summary>The ball was launched (the state it starts from: on the ground plane if it was started just below it).</summary>
        public event Action<FlightState>? Launched;

        /// <summary>The ball came down and, without a bounce model, the flight ended there.</summary>
        public event Action<FlightEvent>? Landed;

        /// <summary>The ball bounced (<see cref="FlightEvent.After"/> is the state leaving the ground).</summary>
        public event Action<FlightEvent>? Bounced;

        /// <summary>The ball's centre crossed a watched plane along its normal (<see cref="FlightEvent.PlaneIndex"/> says which).</summary>
        public event Action<FlightEvent>? PlaneCrossed;

        /// <summary>The ball reached the top of an arc.</summary>
        public event Action<FlightEvent>? ApexReached;

        /// <summary>The ball came to rest (the driver's <see cref="FlightEventKinds.Rest"/> event): the flight has ended (with a bounce model).</summary>
        public event Action<FlightEvent>? Stopped;

        /// <summary>
        /// The ball hit one of the contact shapes (the driver's <see cref="FlightEventKinds.Contact"/> event: its ShapeId, the
        /// index in <see cref="shapeColliders"/> or the caller's id, and ContactNormal); the flight goes on.
        /// </summary>
        public event Action<FlightEvent>? Contacted;

        /// <summary>The driver of the current flight (null before the first launch).</summary>
        public FixedStepDriver? Driver => _driver;

        /// <summary>True from a launch until the flight ends (or <see cref="Cancel"/>).</summary>
        public bool IsFlying => _flying;

        /// <summary>
        /// True when the driver refused a step whose state was not finite (a plain explicit integrator far beyond its
        /// stability limit, once its growth overflows; growth that stays finite is not detected), or whose clock could not advance (a start time near 1e20 s, where a fixed step is below the
        /// time's resolution): the flight ended there, at the last good state. Use the stable RK4 integrator, a shorter
        /// fixed step, or a start time near 0.
        /// </summary>
        public bool Diverged => _driver != null && _driver.Diverged;

        /// <summary>The flight model (built from the inspector at the first use, or given to <see cref="Configure"/>).</summary>
        public FlightModel Model
        {
            get
            {
                EnsureConfigured();
                return _model!;
            }
        }

        /// <summary>The integrator.</summary>
        public IIntegrator Integrator
        {
            get
            {
                EnsureConfigured();
                return _integrator!;
            }
        }

        /// <summary>The fixed step, s.</summary>
        public double FixedStep
        {
            get
            {
                EnsureConfigured();
                return _fixedStep;
            }
        }

        /// <summary>What each step is scanned for: the ground (one radius up), the apex and the watched plane.</summary>
        public FlightEventSet EventSet
        {
            get
            {
                EnsureConfigured();
                return _eventSet!;
            }
        }

        /// <summary>The bounce model, or null when the flight ends at the first landing.</summary>
        public IBounceModel? BounceModel
        {
            get
            {
                EnsureConfigured();
                return _bounce;
            }
        }

        /// <summary>Where the current arc starts: the launch state, or the state leaving the latest bounce.</summary>
        public FlightState ArcStart => _segmentStart;

        /// <summary>Changes at every launch and every bounce: a new <see cref="ArcStart"/> (the trajectory preview watches it).</summary>
        public int ArcVersion => _segmentVersion;

        /// <summary>
        /// Rebuilds the model, integrator, events and bounce from the inspector fields (call it after changing
        /// them at run time; the next launch uses them). Undoes <see cref="Configure"/>.
        /// </summary>
        /// <exception cref="ArgumentException">A field is out of range or the preset unknown (the message names it); nothing changes.</exception>
        public void ApplySettings()
        {
            RequireField(groundHeight, nameof(groundHeight));
            RequireField(maxFrameDelta, nameof(maxFrameDelta));
            if (!(maxFrameDelta > 0))
            {
                throw new ArgumentOutOfRangeException(nameof(maxFrameDelta), maxFrameDelta, FormattableString.Invariant($"maxFrameDelta must be > 0 s; got {maxFrameDelta}."));
            }

            if (watchPlane)
            {
                RequireField(planePoint, nameof(planePoint));
                RequireField(planeNormal, nameof(planeNormal));
                if (planeNormal.x == 0 && planeNormal.y == 0 && planeNormal.z == 0)
                {
                    throw new ArgumentException("planeNormal must not be zero (it is the watched plane's normal).", nameof(planeNormal));
                }
            }

            FlightModel model = settings.CreateModel(Gravity.YUp);
            IBounceModel? bounce = settings.CreateBounce();
            Vector3d up = UnityFrame.Up;
            var ground = new Plane(up * (groundHeight + model.Ball.Radius), up);
            FlightEventSet events = watchPlane
                ? new FlightEventSet(up, ground, new[] { new Plane(UnityFrame.ToLibrary(planePoint), UnityFrame.ToLibrary(planeNormal)) })
                : new FlightEventSet(up, ground);
            IIntegrator chosen = FlightSettings.Integrator(integrator);
            ContactShape[]? shapes = null;
            if (shapeColliders != null && shapeColliders.Count > 0)
            {
                RequireField(shapeRestitution, nameof(shapeRestitution));
                RequireField(shapeFriction, nameof(shapeFriction));
                if (!(shapeRestitution >= 0 && shapeRestitution <= 1))
                {
                    throw new ArgumentOutOfRangeException(nameof(shapeRestitution), shapeRestitution, FormattableString.Invariant($"shapeRestitution must be in [0, 1]; got {shapeRestitution}."));
                }

                if (!(shapeFriction >= 0))
                {
                    throw new ArgumentOutOfRangeException(nameof(shapeFriction), shapeFriction, FormattableString.Invariant($"shapeFriction must be >= 0; got {shapeFriction}."));
                }

                shapes = ColliderShapes.FromColliders(shapeColliders.ToArray(), new ContactProperties(shapeRestitution, shapeFriction));
            }

            Set(model, chosen, fixedStep, events, bounce, maxFrameDelta, shapes);
            _configuredInCode = false;
        }

        /// <summary>
        /// Uses a model, integrator, fixed step, event set and bounce built in code instead of the inspector's
        /// (for example a scene's shared settings); the next launch uses them.
        /// </summary>
        /// <param name="model">The flight model (Unity's world: gravity along -y for a y-up scene).</param>
        /// <param name="integratorToUse">The integrator.</param>
        /// <param name="fixedStepSeconds">The fixed step, s; finite and &gt; 0.</param>
        /// <param name="events">What to scan each step for; its ground is where the ball's centre touches down.</param>
        /// <param name="bounce">The bounce model, or null: the flight ends at the first landing.</param>
        /// <param name="maxFrameDeltaSeconds">The frame-time clamp, s; finite and &gt; 0, and at least the fixed step (frames are cut to it).</param>
        /// <param name="shapes">Contact shapes the ball hits in flight (copied by the driver), or null for none (<see cref="ColliderShapes"/> builds them from colliders).</param>
        /// <exception cref="ArgumentException">A value is null or out of range (the message names it); nothing changes.</exception>
        public void Configure(
            FlightModel model, IIntegrator integratorToUse, double fixedStepSeconds, FlightEventSet events, IBounceModel? bounce,
            double maxFrameDeltaSeconds = FixedStepDriver.DefaultMaxFrameDeltaSeconds, ContactShape[]? shapes = null)
        {
            Set(model, integratorToUse, fixedStepSeconds, events, bounce, maxFrameDeltaSeconds, shapes);
            _configuredInCode = true;
        }

        /// <summary>Launches the ball from the transform's position.</summary>
        /// <param name="velocity">Launch velocity, m/s, in world coordinates.</param>
        /// <param name="angularVelocity">Spin, rad/s, about world axes by Unity's left-hand rule.</param>
        /// <exception cref="ArgumentException">A component is not finite, the configuration is out of range, or, without a bounce model, the
        /// transform is more than <see cref="GroundTolerance"/> below the ground plane and the launch not rising; nothing changes.</exception>
        public void Launch(Vector3 velocity, Vector3 angularVelocity) =>
            Launch(new FlightState(UnityFrame.ToLibrary(transform.position), UnityFrame.ToLibrary(velocity), UnityFrame.ToLibrary(angularVelocity)));

        /// <summary>
        /// Launches the ball from the transform's position with spin given by its effect, right in any
        /// handedness: topspin makes it dip (negative: backspin, it floats), sidespin curls it to the left of
        /// its direction of travel seen from above (negative: to the right).
        /// </summary>
        /// <param name="velocity">Launch velocity, m/s, in world coordinates (not vertical when there is spin).</param>
        /// <param name="topspinRpm">Topspin, rev/min; negative for backspin.</param>
        /// <param name="sidespinRpm">Sidespin, rev/min; positive curls to the left.</param>
        /// <exception cref="ArgumentException">
        /// A value is not finite, there is spin and the velocity is vertical or zero (no spin axis across the
        /// flight is defined), the configuration is out of range, or, without a bounce model, the transform is more than
        /// <see cref="GroundTolerance"/> below the ground plane and the launch not rising; nothing changes.
        /// </exception>
        public void Launch(Vector3 velocity, float topspinRpm, float sidespinRpm)
        {
            RequireFinite(topspinRpm, nameof(topspinRpm));
            RequireFinite(sidespinRpm, nameof(sidespinRpm));
            Vector3d v = UnityFrame.ToLibrary(velocity);
            Launch(new FlightState(UnityFrame.ToLibrary(transform.position), v, SpinByEffect(v, topspinRpm, sidespinRpm)));
        }

        /// <summary>Launches the ball from a state in double precision (its time is the flight's start time).</summary>
        /// <param name="start">Position, m; velocity, m/s; spin, rad/s (left-hand rule); all finite.</param>
        /// <exception cref="ArgumentException">A component is not finite, the configuration is out of range, or, without a bounce model, the
        /// ball's centre is more than <see cref="GroundTolerance"/> below the ground plane and not rising (within it, it is lifted onto the
        /// plane); nothing changes.</exception>
        public void Launch(in FlightState start)
        {
            RequireFiniteStart(start);
            EnsureConfigured();
            // Build first, swap after: a refused start throws with the old flight intact.
            StartFlight(Build(start, _model!, _integrator!, _fixedStep, _eventSet!, _bounce, _maxFrameDelta, _shapes));
        }

        /// <summary>
        /// Configures and launches in one call, all or nothing: <see cref="Configure"/> with these values, then
        /// <see cref="Launch(in FlightState)"/>, except that when either refuses, the configuration and the current flight are
        /// both as they were (with the two calls, a refused start would leave the new configuration in place). For a
        /// scene that builds its settings anew at every launch.
        /// </summary>
        /// <param name="start">Position, m; velocity, m/s; spin, rad/s (left-hand rule); all finite.</param>
        /// <param name="model">The flight model (Unity's world: gravity along -y for a y-up scene).</param>
        /// <param name="integratorToUse">The integrator.</param>
        /// <param name="fixedStepSeconds">The fixed step, s; finite and &gt; 0.</param>
        /// <param name="events">What to scan each step for; its ground is where the ball's centre touches down.</param>
        /// <param name="bounce">The bounce model, or null: the flight ends at the first landing.</param>
        /// <param name="maxFrameDeltaSeconds">The frame-time clamp, s; finite and &gt; 0, and at least the fixed step.</param>
        /// <param name="shapes">Contact shapes the ball hits in flight, or null for none.</param>
        /// <exception cref="ArgumentException">A value is null, not finite or out of range, or the start is refused as
        /// <see cref="Launch(in FlightState)"/> refuses it (the message names which); nothing changes.</exception>
        public void Launch(
            in FlightState start, FlightModel model, IIntegrator integratorToUse, double fixedStepSeconds, FlightEventSet events,
            IBounceModel? bounce, double maxFrameDeltaSeconds = FixedStepDriver.DefaultMaxFrameDeltaSeconds, ContactShape[]? shapes = null)
        {
            RequireFiniteStart(start);
            CheckConfiguration(model, integratorToUse, fixedStepSeconds, events, bounce, maxFrameDeltaSeconds, shapes);
            FixedStepDriver driver = Build(start, model, integratorToUse, fixedStepSeconds, events, bounce, maxFrameDeltaSeconds, shapes);
            Assign(model, integratorToUse, fixedStepSeconds, events, bounce, maxFrameDeltaSeconds, shapes);
            _configuredInCode = true;
            StartFlight(driver);
        }

        private static void RequireFiniteStart(in FlightState start)
        {
            if (!start.IsFinite)
            {
                throw new ArgumentException($"start must have finite position, velocity, spin and time; got {start}.", nameof(start));
            }
        }

        // The driver for a start under a configuration; refuses (throws) before anything is changed.
        private static FixedStepDriver Build(
            in FlightState start, FlightModel model, IIntegrator integratorToUse, double step, FlightEventSet events, IBounceModel? bounce, double maxFrame,
            ContactShape[]? shapes)
        {
            FlightState from = OnOrAboveTheGround(start, events, bounce);
            return new FixedStepDriver(model, integratorToUse, step, from, events, bounce, maxFrame, shapes: shapes);
        }

        // The arc starts, and the transform is put, where the driver starts: with a bounce model the flight core moves a start
        // on or below the court onto it (rolling), so that is not always the start given.
        private void StartFlight(FixedStepDriver driver, bool announce = true)
        {
            FlightState from = driver.State;
            if (_events.Length < driver.MaximumEventsPerStep)
            {
                _events = new FlightEvent[driver.MaximumEventsPerStep]; // at a launch, never per frame
            }

            _driver = driver;
            _flying = true;
            _segmentStart = from;
            _segmentVersion++;
            transform.position = UnityFrame.ToUnity(from.Position);
            if (!announce)
            {
                return; // the same flight under new settings (OnValidate): not a launch
            }

            Launched?.Invoke(from);
            if (_driver == driver)
            {
                onLaunched?.Invoke(); // not when a C# handler has relaunched or cancelled
            }
        }

        // A landing is a crossing of the ground plane from above, so a flight without a bounce model started below it and
        // not rising never lands: it fell for ever. Within GroundTolerance (a transform placed on the plane in floats) the
        // start is lifted onto the plane; deeper is refused. Rising starts and flights with a bounce model are left as given.
        private static FlightState OnOrAboveTheGround(in FlightState start, FlightEventSet events, IBounceModel? bounce)
        {
            if (!(events.Ground is Plane ground) || bounce != null)
            {
                return start; // with a bounce model the flight core puts a ball below the court onto it (FlightStepper.Restart)
            }

            double below = -ground.SignedDistance(start.Position);
            if (!(below > 0) || Vector3d.Dot(start.Velocity, ground.Normal) > 0)
            {
                return start; // on or above the plane, or rising through it: it comes down through the plane later
            }

            if (below > GroundTolerance)
            {
                throw new ArgumentException(
                    FormattableString.Invariant(
                        $"start: the ball's centre is {below:G6} m below the ground plane (the touchdown plane, groundHeight plus the ball's radius, ")
                    + FormattableString.Invariant($"unless Configure gave another) and, not rising and without a bounce model, would never land; launch it from on or above that plane (a tolerance of {GroundTolerance} m) or upward."),
                    "start");
            }

            // Along the normal by the depth; on a tilted plane rounding can leave it a hair below, so it is moved on by that
            // (at most a few passes: each step is at least the depth left, and a double's spacing grows by powers of two).
            Vector3d position = start.Position;
            for (int pass = 0; pass < 8 && below > 0; pass++)
            {
                double size = Math.Max(Math.Abs(position.X), Math.Max(Math.Abs(position.Y), Math.Abs(position.Z)));
                position += ground.Normal * (pass == 0 ? below : below + size * 1e-15);
                below = -ground.SignedDistance(position);
            }

            return new FlightState(position, start.Velocity, start.AngularVelocity, start.Time);
        }

        /// <summary>
        /// Ends the flight where it is, without an event: the component stops moving the transform and
        /// <see cref="Driver"/> is null until the next launch.
        /// </summary>
        public void Cancel()
        {
            _flying = false;
            _driver = null;
        }

        /// <summary>
        /// The angular velocity, rad/s, of <paramref name="topspinRpm"/> topspin and <paramref name="sidespinRpm"/>
        /// sidespin for a ball moving along <paramref name="velocity"/> in Unity's world (up = +y), built with
        /// <see cref="Spin.Topspin"/>, <see cref="Spin.Backspin"/> and <see cref="Spin.Toward"/>.
        /// </summary>
        /// <param name="velocity">Velocity, m/s.</param>
        /// <param name="topspinRpm">Topspin, rev/min; negative for backspin.</param>
        /// <param name="sidespinRpm">Sidespin, rev/min; positive curls to the left of the direction of travel.</param>
        /// <exception cref="ArgumentException">
        /// There is spin and <paramref name="velocity"/> is vertical, zero or not finite (no spin axis across the
        /// flight is defined), or a rate is not finite.
        /// </exception>
        public static Vector3d SpinByEffect(Vector3d velocity, double topspinRpm, double sidespinRpm)
        {
            RequireFinite(topspinRpm, nameof(topspinRpm)); // a NaN rate would otherwise add no spin, silently
            RequireFinite(sidespinRpm, nameof(sidespinRpm));
            Vector3d up = UnityFrame.Up;
            Vector3d spin = Vector3d.Zero;
            // The same test as Spin.Toward's (the sine of the angle between the velocity and up), made here so that
            // a vertical launch is reported as this method's velocity, not as the helpers' up or direction.
            if ((topspinRpm != 0 || sidespinRpm != 0) &&
                !(velocity.IsFinite && Vector3d.Cross(velocity.NormalizedOrZero(), up).Length > 1e-12))
            {
                throw new ArgumentException(
                    $"velocity must be finite and not vertical or zero when there is spin (no spin axis across the flight is defined); got {velocity}.",
                    nameof(velocity));
            }

            if (topspinRpm > 0)
            {
                spin += Spin.Topspin(velocity, up, Spin.FromRpm(topspinRpm));
            }
            else if (topspinRpm < 0)
            {
                spin += Spin.Backspin(velocity, up, Spin.FromRpm(-topspinRpm));
            }

            if (sidespinRpm != 0)
            {
                // Left of the direction of travel seen from above. Unity is left-handed: right = up x forward,
                // so left = forward x up (for a ball flying along +x, left is +z).
                Vector3d left = Vector3d.Cross(velocity, up);
                spin += Spin.Toward(velocity, sidespinRpm > 0 ? left : -left, Spin.FromRpm(Math.Abs(sidespinRpm)));
            }

            return spin;
        }
    }
}
