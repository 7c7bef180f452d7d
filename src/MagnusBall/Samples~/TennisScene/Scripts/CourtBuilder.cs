using MagnusBall.Components;
using UnityEngine;

namespace MagnusBall.Samples.TennisScene.Scripts
{
    /// <summary>
    /// Builds the court from primitives at Start, to the ITF dimensions in <see cref="TennisCourt"/>: the
    /// surface, every line, the net (0.914 m at the centre strap rising to 1.07 m at the posts) and the posts.
    /// The court lies in the x-z plane with the net along z at x = 0 (the thesis's axes: x into the screen,
    /// y up, z to the left).
    /// </summary>
    /// <remarks>
    /// Everything is built under one child, "Court". Start builds only if there is none, so a court built in
    /// edit mode with the "Build court" context menu (and saved with the scene) is not built again on Play;
    /// the context menu replaces an existing court. The parts share four materials (surface, run-off, lines,
    /// net), copied once per build from the primitives' shared material and assigned as sharedMaterial:
    /// reading <c>renderer.material</c> would instantiate a copy per part, which in edit mode leaks into the
    /// scene. A rebuild destroys the previous build's materials, found on the old court's parts by their name (so also
    /// after a domain reload or with the scene reopened, when this component's fields are new); no other material is touched.
    /// </remarks>
    public class CourtBuilder : MonoBehaviour
    {
        public Color surfaceColor = new Color(0.24f, 0.45f, 0.30f, 1f);
        public Color runoffColor = new Color(0.30f, 0.52f, 0.36f, 1f);
        public Color lineColor = Color.white;
        public Color netColor = new Color(0.1f, 0.1f, 0.1f, 1f);
        [Tooltip("Vertical slices of the net, to follow the cord from the posts down to the centre strap.")]
        public int netSegments = 16;

        /// <summary>The name of the child everything is built under.</summary>
        public const string RootName = "Court";

        private const float LineThickness = 0.002f; // lines stand 2 mm proud of the surface so they draw on top

        private Transform _root;
        private Material _surface, _runoff, _line, _net;

        private void Start()
        {
            if (transform.Find(RootName) == null)
            {
                Build();
            }
        }

        /// <summary>Creates the court's objects under a child "Court" of this transform, replacing an existing one.</summary>
        [ContextMenu("Build court")]
        public void Build()
        {
            Transform existing = transform.Find(RootName);
            if (existing != null)
            {
                DestroyBuiltMaterials(existing);
                DestroyImmediate(existing.gameObject); // the context menu runs in edit mode, where Destroy is not allowed
            }

            var root = new GameObject(RootName);
            root.transform.SetParent(transform, false);
            _root = root.transform;
            _surface = null;
            _runoff = null;
            _line = null;
            _net = null;

            Paint(Box("runoff", new Vector3d(0, -0.011, 0), new Vector3d(TennisCourt.Length + 12, 0.02, TennisCourt.DoublesWidth + 8)), ref _runoff, runoffColor, "run-off");
            Paint(Box("court", new Vector3d(0, -0.005, 0), new Vector3d(TennisCourt.Length, 0.01, TennisCourt.DoublesWidth)), ref _surface, surfaceColor, "surface");

            foreach (CourtLine line in TennisCourt.Lines())
            {
                // Each line is drawn inside the court's outline: the dimensions are to the lines' outer edges.
                Vector3d along = line.End - line.Start;
                double length = along.Length;
                Vector3d middle = (line.Start + line.End) * 0.5;
                Vector3d inward = new Vector3d(-System.Math.Sign(middle.X), 0, -System.Math.Sign(middle.Z)) * (TennisCourt.LineWidth / 2);
                bool runsAlongX = System.Math.Abs(along.X) > System.Math.Abs(along.Z);
                Vector3d centre = middle + (runsAlongX ? new Vector3d(0, 0, inward.Z) : new Vector3d(inward.X, 0, 0));
                Vector3d size = runsAlongX
                    ? new Vector3d(length, LineThickness, TennisCourt.LineWidth)
                    : new Vector3d(TennisCourt.LineWidth, LineThickness, length);
                Paint(Box(line.Name, centre + TennisCourt.Up * (LineThickness / 2), size), ref _line, lineColor, "lines");
            }

            double half = TennisCourt.PostOffset;
            double width = 2 * half / netSegments;
            for (int i = 0; i < netSegments; i++)
            {
                double z = -half + (i + 0.5) * width;
                double height = TennisCourt.NetHeightAt(z);
                Paint(Box("net", new Vector3d(0, height / 2, z), new Vector3d(0.02, height, width)), ref _net, netColor, "net");
            }

            foreach (double z in new[] { -half, half })
            {
                GameObject post = GameObject.CreatePrimitive(PrimitiveType.Cylinder);
                post.name = "net post";
                post.transform.SetParent(_root, false);
                // A Unity cylinder is 2 units tall: scale y by half the height.
                post.transform.localPosition = UnityFrame.ToUnity(new Vector3d(0, TennisCourt.NetHeightAtPosts / 2, z));
                post.transform.localScale = new Vector3(0.08f, (float)(TennisCourt.NetHeightAtPosts / 2), 0.08f);
                Paint(post, ref _net, netColor, "net");
            }
        }

        private GameObject Box(string name, Vector3d centre, Vector3d size)
        {
            GameObject box = GameObject.CreatePrimitive(PrimitiveType.Cube);
            box.name = name;
            box.transform.SetParent(_root, false);
            box.transform.localPosition = UnityFrame.ToUnity(centre);
            box.transform.localScale = UnityFrame.ToUnity(size);
            return box;
        }

        // One material per colour per build, copied from the primitive's shared default material and named as this
        // builder's (what DestroyBuiltMaterials looks for).
        private void Paint(GameObject part, ref Material material, Color color, string what)
        {
            Renderer renderer = part.GetComponent<Renderer>();
            if (material == null)
            {
                material = new Material(renderer.sharedMaterial) { color = color, name = MaterialPrefix + what };
            }

            renderer.sharedMaterial = material;
        }

        /// <summary>The name every material a build makes starts with.</summary>
        public const string MaterialPrefix = "MagnusBall court: ";

        // The materials an earlier build made (at most four, shared by the parts), each destroyed once.
        private static void DestroyBuiltMaterials(Transform court)
        {
            for (int i = 0; i < court.childCount; i++)
            {
                Renderer renderer = court.GetChild(i).GetComponent<Renderer>();
                Material material = renderer != null ? renderer.sharedMaterial : null;
                if (material != null && material.name != null && material.name.StartsWith(MaterialPrefix, System.StringComparison.Ordinal))
                {
                    DestroyImmediate(material); // the parts sharing it now hold Unity's destroyed-object null
                }
            }
        }
    }
}
