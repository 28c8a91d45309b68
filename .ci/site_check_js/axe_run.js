// axe-core's violations on the page: [rule, impact, elements, where (first two)].
async () => {
    const result = await axe.run(document, {resultTypes: ["violations"]});
    return result.violations.map(v => [v.id, v.impact, v.nodes.length,
        v.nodes.slice(0, 2).map(n => n.target.join(" ")).join(", ")]);
}
